# SPDX-License-Identifier: GPL-3.0-or-later
# The session never asks which protocol it speaks: it asks its codec
# (core/protocol/codec.h) what to send and what the controller can do, and
# the facts are the dialect's row. This check reads every source under
# core/session and fails naming each place that tests a dialect, its family
# or framing, or writes or reads a dialect's bytes itself. The dialect is
# only passed on (to make the codec, to the firmware table) and named in
# messages.
#
#   cmake -DSESSION=path/to/core/session -P check-session-dialects.cmake

cmake_minimum_required(VERSION 3.25)

# pattern = what it is
set(tests
    "isSpid|isGs232=a dialect family test"
    "Dialect::[A-Za-z0-9]+=a dialect named in code"
    "DialectFamily::|Framing::=a family or framing test"
    "[.]dialect[ \t]*[!=]=|[!=]=[ \t]*[a-zA-Z_.>()-]*[.]dialect=a comparison of dialects"
    "spid::=SPID's frames, outside the codec"
    "protocol::encode[A-Za-z]*[ \t]*[(]=the encoder, outside the codec"
    "protocol::Parser=a parser, outside the codec"
    "dialectSupports[ \t]*[(]|setsBothAxesTogether|rotorsOnLine[ \t]*[(]|angleDecimals[ \t]*[(]|dialectRow[ \t]*[(]=a dialect's facts read past the codec")

file(GLOB files RELATIVE ${SESSION} ${SESSION}/*.h ${SESSION}/*.cpp)
list(LENGTH files scanned)
if(scanned EQUAL 0)
    message(FATAL_ERROR "no sources in ${SESSION}")
endif()
set(faults "")
foreach(file ${files})
    # One list item a line: the characters a CMake list reads (; [ ]) are
    # set aside first, so a line is never split or joined.
    file(READ ${SESSION}/${file} text)
    string(REPLACE ";" "<sc>" text "${text}")
    string(REPLACE "[" "<lb>" text "${text}")
    string(REPLACE "]" "<rb>" text "${text}")
    string(REPLACE "\n" ";" lines "${text}")
    set(number 0)
    foreach(line IN LISTS lines)
        math(EXPR number "${number} + 1")
        string(REGEX REPLACE "//.*" "" code "${line}") # comments say what things are
        string(REPLACE "<sc>" ";" code "${code}")
        string(REPLACE "<lb>" "[" code "${code}")
        string(REPLACE "<rb>" "]" code "${code}")
        foreach(test ${tests})
            string(FIND "${test}" "=" at REVERSE)
            string(SUBSTRING "${test}" 0 ${at} pattern)
            math(EXPR after "${at} + 1")
            string(SUBSTRING "${test}" ${after} -1 what)
            if(code MATCHES "${pattern}")
                string(STRIP "${code}" shown)
                string(REPLACE ";" "" shown "${shown}") # a list item of its own otherwise
                list(APPEND faults "core/session/${file}:${number}: ${what}: ${shown}")
            endif()
        endforeach()
    endforeach()
endforeach()
if(faults)
    list(JOIN faults "\n  " text)
    message(FATAL_ERROR "the session asks which protocol it speaks (ask the codec, protocol/codec.h):\n  ${text}")
endif()
message(STATUS "core/session asks its codec, never the dialect (${scanned} files read)")
