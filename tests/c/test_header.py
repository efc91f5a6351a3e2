"""eyebot.h and eyebot++.h: warning-free as C99, C11, C++17 and C++20, the spec's constant values, what
older programs rely on, and clear failures for names that are gone. No RoBIOS call, no connection."""

from __future__ import annotations

import subprocess

import pytest

from eyesim.programs import toolchain

PROGRAM = r"""
#include "eyebot.h"
#include <stdio.h>
#include <string.h>

static int failures;
#define EXPECT(cond) do { if (!(cond)) { printf("FAIL: %s\n", #cond); failures++; } } while (0)

/* Never called: type-checks every declaration, and that key comparisons draw no warnings. */
void use_every_function(void);
void use_every_function(void)
{
    int a, b, c, d;
    if (KEYGet() == ANYKEY || KEYRead() == KEY_ESCAPE || KEYRead() == KEY_INVALID) {}
    switch (KEYGet()) { case KEY1: case KEY4: case ANYKEY: case KEY_ESCAPE: case KEY_LIST8: break; default: break; }
    LCDPrintf("%d %s\n", 1, "x");
    LCDSetPrintf(1, 2, "%5.1f", 1.5);
    LCDClear();
    LCDMenu("GO", "", " ", "END");
    OSWait(10);
    (void)OSGetCount();
    (void)PSDGet(PSD_FRONT);
    VWSetSpeed(100, -30);
    VWGetSpeed(&a, &b);
    VWSetPosition(1, 2, 3);
    VWGetPosition(&a, &b, &c);
    VWStraight(-1000, 300);
    VWTurn(180, 60);
    while (!VWDone()) {}
    VWWait();
    (void)VWDriveDone();
    VWDriveWait();
    SIMGetRobot(0, &a, &b, &c, &d);
    SIMSetRobot(0, 500, 500, 0, 180);
}

/* Never called either: the image functions with the typedef'd image types. */
void use_image_functions(void);
void use_image_functions(void)
{
    static QVGAcol col, col2;
    static QVGAgray gray, gray2, h, s, i;
    BYTE r, g, b;
    const BYTE *input = gray;
    IPSetSize(QVGA);
    (void)IPReadFile("in.ppm", col);
    IPWriteFile("out.ppm", col);
    IPWriteFileGray("out.pgm", input);
    IPLaplace(input, gray2);
    IPSobel(gray, gray);
    IPCol2Gray(col, gray);
    IPGray2Col(gray, col);
    IPRGB2Col(h, s, i, col);
    IPCol2HSI(col, h, s, i);
    IPOverlay(col, col2, col);
    IPOverlayGray(gray, gray2, RED, col);
    IPPCol2RGB(IPPRGB2Col(1, 2, 3), &r, &g, &b);
    IPPCol2HSI(ORANGE, &r, &g, &b);
    r = IPPRGB2Hue(r, g, b);
    IPPRGB2HSI(r, g, b, &h[0], &s[0], &i[0]);
    (void)(IP_WIDTH + IP_HEIGHT + IP_PIXELS + IP_SIZE);
}

int main(void)
{
    COLOR colour = ORANGE;
    BYTE pixel = 255;
    TIMER timer = 0;
    (void)timer;
    EXPECT(colour == 0xFFA500 && pixel == 255 && sizeof(BYTE) == 1);
    EXPECT(NOKEY == 0 && KEY1 == 1 && KEY2 == 2 && KEY3 == 4 && KEY4 == 8);
    EXPECT(ANYKEY == -1 && (unsigned)ANYKEY == 0xFFFFFFFFu && (unsigned)KEY_INVALID == 0xFFFFFFFFu);
    EXPECT((unsigned)KEY_ESCAPE == 0x80000000u && KEY_LISTTL == 0x40000000 && KEY_LIST1 == 0x10 && KEY_LIST8 == 0x800);
    EXPECT(KEYTM_CLASSIC == 1 && KEYTM_LISTMENU == 4);
    EXPECT(RED == 0xFF0000 && GREEN == 0x00FF00 && BLUE == 0x0000FF && WHITE == 0xFFFFFF && BLACK == 0);
    EXPECT(GRAY == 0x808080 && SILVER == 0xC0C0C0 && LIGHTGRAY == 0xD3D3D3 && DARKGRAY == 0xA9A9A9);
    EXPECT(NAVY == 0x000080 && CYAN == 0x00EEEE && TEAL == 0x008080 && MAGENTA == 0xFF00FF);
    EXPECT(PURPLE == 0x800080 && MAROON == 0x800000 && YELLOW == 0xFFFF00 && OLIVE == 0x9ACD32);
    EXPECT(QQVGA == 0 && QVGA == 1 && VGA == 2 && CAM1MP == 3 && CAMHD == 4 && CAM5MP == 5 && CUSTOM == 10);
    EXPECT(QQVGA_X == 160 && QQVGA_Y == 120 && QQVGA_PIXELS == 19200 && QQVGA_SIZE == 57600);
    EXPECT(QVGA_PIXELS == 76800 && QVGA_SIZE == 230400 && VGA_PIXELS == 307200 && VGA_SIZE == 921600);
    EXPECT(CAM1MP_X == 1296 && CAM1MP_Y == 730 && CAM1MP_PIXELS == 946080 && CAM1MP_SIZE == 2838240);
    EXPECT(CAMHD_PIXELS == 2073600 && CAMHD_SIZE == 6220800 && CAM5MP_PIXELS == 5038848 && CAM5MP_SIZE == 15116544);
    EXPECT(sizeof(QQVGAcol) == 57600 && sizeof(QQVGAgray) == 19200 && sizeof(QVGAcol) == 230400);
    EXPECT(sizeof(VGAgray) == 307200 && sizeof(CAM1MPcol) == 2838240 && sizeof(CAMHDgray) == 2073600);
    EXPECT(sizeof(CAM5MPcol) == 15116544 && sizeof(CAM5MPgray) == 5038848 && sizeof(VGAcol) == 921600);
    EXPECT(HELVETICA == 0 && TIMES == 1 && COURIER == 2 && NORMAL == 0 && BOLD == 1 && ITALICS == 2);
    EXPECT(LCD_BGCOL_TRANSPARENT == 0x01 && LCD_BGCOL_NOTRANSPARENT == 0x10 && LCD_FGCOL_NOINVERSE == 0x40);
    EXPECT(LCD_AUTOREFRESH == 1 && LCD_NOAUTOREFRESH == 0x100 && LCD_CLASSICMENU == 0x1000);
    EXPECT(LCD_FB_ROTATE == 0x80 && LCD_FB_NOROTATION == 0x8000 && LCD_HIDEMENU == 0x800);
    EXPECT(PSD_FRONT == 1 && PSD_LEFT == 2 && PSD_RIGHT == 3 && PSD_BACK == 4);
    EXPECT(VEHICLE == 1 && PLATFORM == 2 && WALKER == 3 && MACHINE_SPEED == 700000000 && MACHINE_ID == 1);
    EXPECT(strcmp(MACHINE_NAME, "EyeBot") == 0 && strcmp(VERSION, "1.0") == 0);
    EXPECT(MENU_HEIGHT == 38 && LCD_MENU_STRLENGTH == 32 && LCD_LIST_STRLENGTH == 64);
    EXPECT(CAM_SUCCESS == 0 && CAM_FAILURE == 1 && IOBOARD == 1 && True == 1 && False == 0);
    EXPECT(IRTV_0 == '0' && IRTV_9 == '9' && IRTV_RIGHT == '>' && IRTV_POWER == 'P');
    printf("ok\n");
    return failures != 0;
}
"""


STANDARDS = [("cc", "-std=c99"), ("cc", "-std=c11"), ("c++", "-std=c++17"), ("c++", "-std=c++20")]
CXX_STANDARDS = [s for s in STANDARDS if s[0] == "c++"]


def run_offline(exe, env) -> subprocess.CompletedProcess:
    # No RoBIOS call connects, so these run with no simulator anywhere.
    return subprocess.run([str(exe)], capture_output=True, text=True, timeout=10, env=env)


@pytest.mark.parametrize("language,standard", STANDARDS)
def test_header_compiles_cleanly_and_has_the_spec_values(compiler, free_port_env, language, standard):
    exe = compiler.build(PROGRAM, name="header_check", language=language, flags=(standard, "-Wpedantic"))
    ran = run_offline(exe, free_port_env)
    assert ran.returncode == 0, ran.stdout + ran.stderr
    assert ran.stdout == "ok\n"
    assert ran.stderr == ""


def compile_only(prefix, tmp_path, language, standard, source, name="only", include_dirs=()):
    path = tmp_path / (f"{name}.c" if language == "cc" else f"{name}.cpp")
    path.write_text(source)
    flags = [standard, "-Wall", "-Wextra", "-Wpedantic", "-Werror", *(f"-I{d}" for d in include_dirs)]
    command = toolchain.compiler_command(language, [*flags, "-c", str(path), "-o", str(tmp_path / f"{name}.o")], prefix)
    return subprocess.run(command, capture_output=True, text=True)


@pytest.mark.parametrize("language,standard", STANDARDS)
def test_header_compiles_on_its_own(robios_prefix, tmp_path, language, standard):
    done = compile_only(robios_prefix, tmp_path, language, standard, '#include "eyebot.h"\n')
    assert done.returncode == 0, done.stderr


@pytest.mark.parametrize("language,standard", CXX_STANDARDS)
def test_cplusplus_header_compiles_on_its_own(robios_prefix, tmp_path, language, standard):
    done = compile_only(robios_prefix, tmp_path, language, standard, '#include "eyebot++.h"\n')
    assert done.returncode == 0, done.stderr


CPLUSPLUS_LAB = r"""
#include "eyebot++.h"

int distance = 5, count = 2, left = 1, right = 1; // names a `using namespace std` would make ambiguous

int main()
{
    std::vector<int> v{3, 1, 2};
    std::sort(v.begin(), v.end());
    std::map<std::string, int> seen{{"a", 1}};
    std::ostringstream out;
    out << v[0] << v[1] << v[2] << " " << seen["a"] << " " << std::max(distance, count);
    printf("%s %.3f %d\n", out.str().c_str(), sqrt(2.0), abs(-(left + right)));
    QVGAcol image{};
    std::array<BYTE, QVGA_PIXELS> gray{};
    std::cout << sizeof image << " " << gray.size() << " " << (KEY4 | ANYKEY) << std::endl;
    return 0;
}
"""


@pytest.mark.parametrize("language,standard", CXX_STANDARDS)
def test_cplusplus_labs_get_the_standard_headers(compiler, free_port_env, language, standard):
    exe = compiler.build(CPLUSPLUS_LAB, name="lab", language=language, flags=(standard, "-Wpedantic"))
    ran = run_offline(exe, free_port_env)
    assert ran.returncode == 0, ran.stderr
    assert ran.stdout == "123 1 5 1.414 2\n230400 76800 -1\n"


def test_cplusplus_header_tells_c_programs_to_use_eyebot_h(robios_prefix, tmp_path):
    done = compile_only(robios_prefix, tmp_path, "cc", "-std=c11", '#include "eyebot++.h"\n')
    assert done.returncode != 0
    assert "eyebot++.h is for C++ programs" in done.stderr


OLDER_PROGRAM = r"""
#include "eyebot.h"
#include <pthread.h>
#include <stdio.h>

static QQVGAcol image;
static QQVGAgray gray;

static void *worker(void *arg) { (void)arg; return NULL; }

int main(void)
{
    pthread_t thread;
    int done = False;
    if (XInitThreads() == 0) return 1; /* X11 convention: non-zero is success */
    pthread_create(&thread, NULL, worker, NULL);
    pthread_join(thread, NULL);
    done = True;
    printf("%d %d %d %d\n", done, LCDInit(), (int)sizeof image, (int)sizeof gray);
    if (0) { VWDriveWait(); (void)VWDriveDone(); }
    return 0;
}
"""


@pytest.mark.parametrize("language,standard", STANDARDS)
def test_older_programs_compile_and_run(compiler, free_port_env, language, standard):
    exe = compiler.build(OLDER_PROGRAM, name="older", language=language, flags=(standard, "-Wpedantic"))
    ran = run_offline(exe, free_port_env)  # LCDInit and XInitThreads need no simulator
    assert ran.returncode == 0, ran.stderr
    assert ran.stdout == "1 0 57600 19200\n"


LITERALS = r"""
#include "eyebot.h"

/* Never called: every function that only reads a text takes a string literal without a warning. */
void texts(void);
void texts(void)
{
    static QQVGAcol image;
    LCDPrintf("plain");
    LCDSetPrintf(1, 2, "x");
    LCDMenu("A", "B", "C", "D");
    LCDMenuI(1, "A", RED, BLACK);
    (void)IPReadFile("in.ppm", image);
    IPWriteFile("out.ppm", image);
    IPWriteFileGray("out.pgm", image);
    (void)OSExecute("ls");
    SERSend(0, "hello");
    AUPlay("beep.wav");
    RADIOSend(2, "hello");
}
"""


@pytest.mark.parametrize("language,standard", STANDARDS)
def test_text_parameters_take_string_literals(robios_prefix, tmp_path, language, standard):
    done = compile_only(robios_prefix, tmp_path, language, standard, LITERALS)
    assert done.returncode == 0, done.stderr


FAKE_XLIB = """#ifndef _X11_XLIB_H_
#define _X11_XLIB_H_
typedef int Status;
#define True 1
#define False 0
extern Status XInitThreads(void);
#endif
"""


@pytest.mark.parametrize("language,standard", STANDARDS)
@pytest.mark.parametrize("xlib_first", [True, False])
def test_xinitthreads_gets_along_with_xlib(robios_prefix, tmp_path, language, standard, xlib_first):
    (tmp_path / "X11").mkdir()
    (tmp_path / "X11" / "Xlib.h").write_text(FAKE_XLIB)  # what matters of the real one, which may be missing
    includes = ["#include <X11/Xlib.h>", '#include "eyebot.h"']
    source = (
        "\n".join(includes if xlib_first else includes[::-1])
        + "\nint f(void);\nint f(void) { return XInitThreads() + True; }\n"
    )
    done = compile_only(robios_prefix, tmp_path, language, standard, source, include_dirs=(tmp_path,))
    assert done.returncode == 0, done.stderr


@pytest.mark.parametrize("language,standard", STANDARDS)
def test_the_legacy_laser_scan_is_declared(robios_prefix, tmp_path, language, standard):
    source = '#include "eyebot.h"\nint f(void);\nint f(void) { int scan[360]; return SIMLaserScan(scan) + scan[0]; }\n'
    done = compile_only(robios_prefix, tmp_path, language, standard, source)
    assert done.returncode == 0, done.stderr


# EyeSim's eyebot.h made the C library available: programs use it with nothing else included.
STANDARD_LIBRARY = r"""
#include "eyebot.h"

static int counted;

static void *count(void *arg)
{
    counted = *(int *)arg;
    return NULL;
}

int main(void)
{
    char words[32], *word;
    int n = 0, argument = 7;
    FILE *out = stdout;
    uint8_t small = 200;
    bool yes = true;
    pthread_t thread;
    srand((unsigned)time(NULL));
    if (rand() > RAND_MAX) return EXIT_FAILURE;
    strcpy(words, "a b c");
    for (word = strtok(words, " "); word; word = strtok(NULL, " ")) n++;
    if (usleep(1000) != 0) return EXIT_FAILURE;
    pthread_create(&thread, NULL, count, &argument);
    pthread_join(thread, NULL);
    fprintf(out, "%d %.3f %.4f %d %d %d %d\n", n, sqrt(2.0), M_PI, small, yes, counted, abs(-3));
    return EXIT_SUCCESS;
}
"""
STANDARD_LIBRARY_OUTPUT = "3 1.414 3.1416 200 1 7 3\n"


@pytest.mark.parametrize("language,standard", [*STANDARDS, ("cc", "-std=gnu11")])
@pytest.mark.parametrize("stdio_first", [False, True])
def test_eyebot_h_brings_the_c_library(compiler, free_port_env, language, standard, stdio_first):
    # With <stdio.h> first the C library's feature set is fixed before eyebot.h can choose it:
    # usleep and M_PI then come from `eyesim cc`'s -D_DEFAULT_SOURCE.
    source = ("#include <stdio.h>\n" if stdio_first else "") + STANDARD_LIBRARY
    exe = compiler.build(source, name="stdlib", language=language, flags=(standard, "-Wpedantic"))
    ran = run_offline(exe, free_port_env)
    assert ran.returncode == 0, ran.stderr
    assert ran.stdout == STANDARD_LIBRARY_OUTPUT


def test_eyebot_h_first_needs_no_feature_macro_from_eyesim_cc(robios_prefix, tmp_path, free_port_env):
    """A plain compiler command (a program's own Makefile) with strict C99: eyebot.h asks for usleep itself."""
    source = tmp_path / "plain.c"
    source.write_text(STANDARD_LIBRARY)
    lib = robios_prefix / "lib"
    done = subprocess.run(
        [
            "cc",
            "-std=c99",
            "-Wall",
            "-Wextra",
            "-Wpedantic",
            "-Werror",
            f"-I{robios_prefix / 'include'}",
            str(source),
            "-o",
            str(tmp_path / "plain"),
            f"-L{lib}",
            f"-Wl,-rpath,{lib}",
            "-leyesim",
            "-lpthread",
            "-lm",
        ],
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stderr
    ran = run_offline(tmp_path / "plain", free_port_env)
    assert ran.returncode == 0, ran.stderr
    assert ran.stdout == STANDARD_LIBRARY_OUTPUT
