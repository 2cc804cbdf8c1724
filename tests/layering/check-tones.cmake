# SPDX-License-Identifier: GPL-3.0-or-later
# The tones a message is shown in (refused, warning) are written once, in
# ui/operatortheme.h; every widget takes them from there. This check reads
# every source under ui/ and fails naming each other place that writes one.
#
#   cmake -DUI=path/to/ui -P check-tones.cmake

cmake_minimum_required(VERSION 3.25)

file(READ ${UI}/operatortheme.h theme)
set(tones "")
foreach(name kRefused kWarning)
    if(NOT theme MATCHES "${name}\\[\\] = \"(#[0-9a-fA-F]+)\"")
        message(FATAL_ERROR "ui/operatortheme.h does not define tone::${name}")
    endif()
    list(APPEND tones ${CMAKE_MATCH_1})
endforeach()

file(GLOB_RECURSE files RELATIVE ${UI} ${UI}/*.h ${UI}/*.cpp)
list(REMOVE_ITEM files operatortheme.h)
set(faults "")
foreach(file ${files})
    file(READ ${UI}/${file} text)
    foreach(tone ${tones})
        string(TOLOWER "${text}" lower)
        string(TOLOWER "${tone}" wanted)
        string(FIND "${lower}" "${wanted}" at)
        if(NOT at EQUAL -1)
            list(APPEND faults "ui/${file}: writes ${tone} (take tone:: from operatortheme.h)")
        endif()
    endforeach()
endforeach()
if(faults)
    list(JOIN faults "\n  " text)
    message(FATAL_ERROR "a tone written outside ui/operatortheme.h:\n  ${text}")
endif()
list(LENGTH files scanned)
message(STATUS "the tones are written once (${scanned} files read)")
