"""LCDPrintf's formatting in Python against the C library's own snprintf: every conversion C
accepts, flags, width, precision, `*`, length modifiers; surplus arguments are ignored."""

from __future__ import annotations

import ctypes

import pytest

libc = ctypes.CDLL(None)


def c_printf(format: str, *args) -> str:
    """What C's printf prints, by snprintf with the given ctypes arguments."""
    buffer = ctypes.create_string_buffer(512)
    libc.snprintf(buffer, ctypes.c_size_t(512), format.encode(), *args)
    return buffer.value.decode()


# (format, Python arguments, the same as C arguments)
I, L, D = ctypes.c_int, ctypes.c_long, ctypes.c_double
CASES = [
    ("%d %i", (42, -7), (I(42), I(-7))),
    ("[%5d|%-5d|%05d|%+d|% d|%+05d]", (42, 42, -42, 5, 5, -3), (I(42), I(42), I(-42), I(5), I(5), I(-3))),
    ("[%.3d|%.0d|%8.3d|%-+6d]", (7, 0, -7, 9), (I(7), I(0), I(-7), I(9))),
    ("%u %lu %hu %hhu", (-1, -1, 70000, 300), (I(-1), L(-1), I(70000), I(300))),
    (
        "%hd %hhd %ld %lld %jd %zd %td",
        (70000, 200, -5, 2**40, 3, 4, -6),
        (I(70000), I(200), L(-5), ctypes.c_longlong(2**40), L(3), L(4), L(-6)),
    ),
    ("%x %X %#x %#X %#o %o %#o", (255, 255, 255, 0, 8, 8, 0), (I(255), I(255), I(255), I(0), I(8), I(8), I(0))),
    (
        "%lx %llX %hx %08x %#010x %-#8o|",
        (-1, -1, -1, 48879, 48879, 8),
        (L(-1), ctypes.c_longlong(-1), I(-1), I(48879), I(48879), I(8)),
    ),
    ("%f %e %g %E %G %F", (3.14159,) * 6, (D(3.14159),) * 6),
    (
        "[%.2f|%10.3e|%-10.1g|%+.0f|% f|%08.2f]",
        (3.14159, 31415.9, 0.0001234, 2.5, 1.5, -3.14159),
        (D(3.14159), D(31415.9), D(0.0001234), D(2.5), D(1.5), D(-3.14159)),
    ),
    (
        "%#g %#.0f %g %g %.10g %.f",
        (1.0, 2.0, 1e-5, 123456789.0, 1 / 3, 2.5),
        (D(1.0), D(2.0), D(1e-5), D(123456789.0), D(1 / 3), D(2.5)),
    ),
    ("%f %e %g", (float("inf"), float("-inf"), float("nan")), (D(float("inf")), D(float("-inf")), D(float("nan")))),
    ("%5.1f%% done", (99.5,), (D(99.5),)),
    ("%d and %f", (3.9, 2), (I(3), D(2.0))),  # an int format takes a float as C code would cast it
    ("[%c%c|%3c|%-3c]", (65, "B", "x", 121), (I(65), I(66), I(ord("x")), I(121))),
    ("[%s|%10s|%-10s|%.2s|%6.2s]", ("abc",) * 5, (b"abc",) * 5),
    (
        "[%*d|%-*d|%.*f|%*d|%*.*f]",
        (5, 42, 5, 42, 2, 3.14159, -5, 42, 8, 3, 2.0),
        (I(5), I(42), I(5), I(42), I(2), D(3.14159), I(-5), I(42), I(8), I(3), D(2.0)),
    ),
    ("%.*f", (-1, 2.5), (I(-1), D(2.5))),  # a negative * precision counts as none
    ("%a %A %a %a %a", (1.5, 1.5, 0.1, -2.0, 0.0), (D(1.5), D(1.5), D(0.1), D(-2.0), D(0.0))),
    ("%%|%5%|100%%", (), ()),
    ("%p %p", (0, 0x1234), (ctypes.c_void_p(0), ctypes.c_void_p(0x1234))),
]


@pytest.mark.parametrize("format,args,c_args", CASES, ids=[case[0] for case in CASES])
def test_formatting_is_c_printf(eye, format, args, c_args):
    from eye._printf import printf

    assert printf("LCDPrintf", format, args) == c_printf(format, *c_args)


def test_surplus_arguments_are_ignored_as_in_c(eye):
    from eye._printf import printf

    assert printf("LCDPrintf", "Hello\n", ("",)) == "Hello\n"
    assert printf("LCDPrintf", "%d apples\n", (3, "extra", 4.5)) == "3 apples\n"


def test_missing_arguments_and_non_conversions_print_as_they_are(eye):
    from eye._printf import printf

    assert printf("LCDPrintf", "100%", ()) == "100%"
    assert printf("LCDPrintf", "50% done %d", ()) == "50% done %d"
    assert printf("LCDPrintf", "%d of %d", (1,)) == "1 of %d"
    assert printf("LCDPrintf", "%y %", ()) == "%y %"
    assert printf("LCDPrintf", 42, ()) == "42"
    assert printf("LCDPrintf", b"bytes %s", (b"ok",)) == "bytes ok"


@pytest.mark.parametrize(
    "format,args,message",
    [
        ("%d", ("12",), "LCDPrintf: %d needs a number, not the text '12'"),
        ("%5.1f", ("x",), "LCDPrintf: %5.1f needs a number, not the text 'x'"),
        ("%c", ("ab",), "LCDPrintf: %c cannot print 'ab'"),
        ("%d", (None,), "LCDPrintf: %d cannot print None"),
    ],
)
def test_arguments_that_do_not_fit_are_clear_errors(eye, format, args, message):
    from eye._printf import printf

    with pytest.raises(TypeError) as error:
        printf("LCDPrintf", format, args)
    assert str(error.value).startswith(message)


def test_percent_n_is_refused(eye):
    from eye._printf import printf

    with pytest.raises(ValueError, match="LCDPrintf: %n is not supported"):
        printf("LCDPrintf", "%d%n", (1, 0))
