# CMake toolchain file: build libeyesim for another system with Zig's C compiler (`zig cc`), from
# the `ziglang` Python package or a `zig` executable.
#
#   cmake -S robios -B build/win -DCMAKE_TOOLCHAIN_FILE=$PWD/robios/cmake/zig.cmake \
#         -DZIG_TARGET=x86_64-windows-gnu
#
# (CMake looks for a relative CMAKE_TOOLCHAIN_FILE in the build directory and then in the source
# directory robios/, so give an absolute path, or `cmake/zig.cmake`.)
#
# ZIG_TARGET is a Zig target triple: x86_64-windows-gnu, aarch64-macos, x86_64-macos,
# x86_64-linux-gnu (optionally with a glibc version: x86_64-linux-gnu.2.17), aarch64-linux-gnu, ...
#
# How Zig is run (the first that applies):
#   -DZIG_EXECUTABLE=/path/to/zig   a zig binary;
#   -DZIG_PYTHON=/path/to/python    `python -m ziglang` with that Python;
#   otherwise the Python of an active virtual environment ($VIRTUAL_ENV), else python3/python on
#   PATH, which must have the ziglang package installed.
#
# CMAKE_C_COMPILER must be a single program, so this file writes small wrapper scripts
# (zig-cc, zig-ar, zig-ranlib, zig-rc; .cmd files on a Windows host) into <build>/zig-toolchain/
# that run `zig cc -target ZIG_TARGET "$@"` and friends.

if(NOT ZIG_TARGET AND DEFINED ENV{ZIG_TARGET})
    set(ZIG_TARGET "$ENV{ZIG_TARGET}")
endif()
if(NOT ZIG_TARGET)
    message(FATAL_ERROR "zig.cmake: set ZIG_TARGET, e.g. -DZIG_TARGET=x86_64-windows-gnu")
endif()

# try_compile() projects read this file again, in their own build directory: hand them the
# settings and the wrappers' directory of the main build.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES ZIG_TARGET ZIG_EXECUTABLE ZIG_PYTHON ZIG_WRAPPER_DIR)

# The system and processor, from the target triple.
string(REPLACE "-" ";" _zig_parts "${ZIG_TARGET}")
list(GET _zig_parts 0 _zig_arch)
list(LENGTH _zig_parts _zig_count)
if(_zig_count LESS 2)
    message(FATAL_ERROR "zig.cmake: ZIG_TARGET '${ZIG_TARGET}' is not arch-os[-abi]")
endif()
list(GET _zig_parts 1 _zig_os)
if(_zig_os MATCHES "^windows")
    set(CMAKE_SYSTEM_NAME Windows)
elseif(_zig_os MATCHES "^macos")
    set(CMAKE_SYSTEM_NAME Darwin)
elseif(_zig_os MATCHES "^linux")
    set(CMAKE_SYSTEM_NAME Linux)
elseif(_zig_os MATCHES "^freebsd")
    set(CMAKE_SYSTEM_NAME FreeBSD)
else()
    message(FATAL_ERROR "zig.cmake: no CMake system name known for ZIG_TARGET '${ZIG_TARGET}'")
endif()
if(_zig_arch STREQUAL "aarch64" AND CMAKE_SYSTEM_NAME STREQUAL "Darwin")
    set(CMAKE_SYSTEM_PROCESSOR arm64)
elseif(_zig_arch STREQUAL "x86_64" AND CMAKE_SYSTEM_NAME STREQUAL "Windows")
    set(CMAKE_SYSTEM_PROCESSOR AMD64)
else()
    set(CMAKE_SYSTEM_PROCESSOR "${_zig_arch}")
endif()

# The command that runs Zig.
if(ZIG_EXECUTABLE)
    set(_zig_command "${ZIG_EXECUTABLE}")
else()
    if(NOT ZIG_PYTHON)
        set(_zig_hints)
        if(DEFINED ENV{VIRTUAL_ENV})
            list(APPEND _zig_hints "$ENV{VIRTUAL_ENV}/bin" "$ENV{VIRTUAL_ENV}/Scripts")
        endif()
        find_program(ZIG_PYTHON NAMES python3 python HINTS ${_zig_hints})
        if(NOT ZIG_PYTHON)
            message(FATAL_ERROR "zig.cmake: no Python found; set ZIG_PYTHON or ZIG_EXECUTABLE")
        endif()
    endif()
    set(_zig_command "${ZIG_PYTHON}" -m ziglang)
endif()

if(NOT ZIG_WRAPPER_DIR)
    set(ZIG_WRAPPER_DIR "${CMAKE_BINARY_DIR}/zig-toolchain")
endif()

# One wrapper per Zig tool. ZIG_TARGET goes into the compiler's wrapper, so that every compile and
# link (also CMake's own checks) targets it.
function(_zig_write_wrapper name)
    set(command ${_zig_command} ${ARGN})
    if(CMAKE_HOST_WIN32)
        set(file "${ZIG_WRAPPER_DIR}/${name}.cmd")
        set(line "")
        foreach(word IN LISTS command)
            string(APPEND line "\"${word}\" ")
        endforeach()
        set(text "@echo off\r\n${line}%*\r\n")
    else()
        set(file "${ZIG_WRAPPER_DIR}/${name}")
        set(line "exec")
        foreach(word IN LISTS command)
            string(REPLACE "'" "'\\''" word "${word}")
            string(APPEND line " '${word}'")
        endforeach()
        set(text "#!/bin/sh\n${line} \"$@\"\n")
    endif()
    # Rewritten only when it changes, so that a reconfigure does not rebuild everything.
    set(old "")
    if(EXISTS "${file}")
        file(READ "${file}" old)
    endif()
    if(NOT old STREQUAL text)
        file(MAKE_DIRECTORY "${ZIG_WRAPPER_DIR}")
        file(WRITE "${file}.tmp" "${text}")
        file(COPY "${file}.tmp" DESTINATION "${ZIG_WRAPPER_DIR}/tmp"
             FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE
                              WORLD_READ WORLD_EXECUTE)
        get_filename_component(base "${file}.tmp" NAME)
        file(RENAME "${ZIG_WRAPPER_DIR}/tmp/${base}" "${file}")
        file(REMOVE "${file}.tmp")
    endif()
    set(_zig_wrapper_${name} "${file}" PARENT_SCOPE)
endfunction()

_zig_write_wrapper(zig-cc cc -target "${ZIG_TARGET}")
_zig_write_wrapper(zig-c++ c++ -target "${ZIG_TARGET}")
_zig_write_wrapper(zig-ar ar)
_zig_write_wrapper(zig-ranlib ranlib)
_zig_write_wrapper(zig-rc rc)

set(CMAKE_C_COMPILER "${_zig_wrapper_zig-cc}")
set(CMAKE_CXX_COMPILER "${_zig_wrapper_zig-c++}")
set(CMAKE_AR "${_zig_wrapper_zig-ar}" CACHE FILEPATH "Archiver (zig ar)")
set(CMAKE_RANLIB "${_zig_wrapper_zig-ranlib}" CACHE FILEPATH "Ranlib (zig ranlib)")
if(CMAKE_SYSTEM_NAME STREQUAL "Windows")
    set(CMAKE_RC_COMPILER "${_zig_wrapper_zig-rc}")
endif()

if(CMAKE_SYSTEM_NAME STREQUAL "Darwin")
    # No Apple SDK here: Zig brings the macOS headers and libSystem stubs itself. Architecture flags
    # come from the target, not from CMAKE_OSX_ARCHITECTURES.
    set(CMAKE_OSX_SYSROOT "" CACHE PATH "" FORCE)
    set(CMAKE_OSX_ARCHITECTURES "" CACHE STRING "" FORCE)
    # install_name_tool does not exist off macOS: link with the install names and rpaths the
    # installed files need, so that installing only copies.
    set(CMAKE_BUILD_WITH_INSTALL_RPATH ON)
    set(CMAKE_BUILD_WITH_INSTALL_NAME_DIR ON)
endif()

# Look for libraries and headers of the target, not of this machine.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
