# SPDX-License-Identifier: GPL-3.0-or-later
# Every option's name is written once, in app/cli/optionnames.h: the table
# that declares the options and every program that reads them take it from
# there (opt::connect). A name written again as a string literal compiles
# whatever its spelling, and a misspelt one silently reads nothing. This
# check reads every source under app/ and fails naming the file and line
#  - where a parser's value(), values() or isSet() is given a string
#    literal, an option's name or not;
#  - where a string literal is an option's name, or --name: a name kept
#    aside (`const QString connect = QStringLiteral("connect")`), a list of
#    names, or argv compared with one.
# A literal that happens to spell a name and means something else is
# listed below, with why.
#
#   cmake -DAPP=path/to/app -P check-option-names.cmake

cmake_minimum_required(VERSION 3.25)

# file:literal, for the literals that spell an option's name and are none.
set(not_options
    # the value's name in --help and the manual (--start <time>)
    cli/slewcommandline.cpp:time cli/slewcommandline.cpp:axis cli/slewcommandline.cpp:hours
    # keys of the JSON that --passes, --where and --schedule print
    slew_sky.cpp:time slew_sky.cpp:refraction slew_schedule.cpp:horizon)

file(STRINGS ${APP}/cli/optionnames.h declarations REGEX "QStringLiteral\\(\"[^\"]+\"\\)")
set(names "")
foreach(declaration ${declarations})
    string(REGEX REPLACE ".*QStringLiteral\\(\"([^\"]+)\"\\).*" "\\1" name "${declaration}")
    list(APPEND names ${name})
endforeach()
list(LENGTH names named)
if(named LESS 10)
    message(FATAL_ERROR "app/cli/optionnames.h: ${named} names read; has its form changed?")
endif()

file(GLOB_RECURSE files RELATIVE ${APP} ${APP}/*.h ${APP}/*.cpp)
list(REMOVE_ITEM files cli/optionnames.h)
set(faults "")
set(not_options_seen "")
foreach(file ${files})
    file(READ ${APP}/${file} text)
    # One list item a line: what CMake would take for a list's separator or
    # brackets is set aside first.
    string(REPLACE ";" "<semicolon>" text "${text}")
    string(REPLACE "[" "<bracket>" text "${text}")
    string(REPLACE "]" "<bracket>" text "${text}")
    string(REPLACE "\\" "<backslash>" text "${text}")
    string(REPLACE "\n" ";" lines "${text}")
    set(number 0)
    foreach(line IN LISTS lines)
        math(EXPR number "${number} + 1")
        # Comments may name options; a `//` inside a URL is no comment.
        string(REGEX REPLACE "(^|[ \t])//.*" "" line "${line}")
        if(line MATCHES "[A-Za-z_]*[Pp]arser[ \t]*(\\.|->)[ \t]*(value|values|isSet)[ \t]*\\([^)]*\"")
            list(APPEND faults "app/${file}:${number}: a parser reads an option by a string literal (take its name from cli/optionnames.h)")
        endif()
        # Escaped and single quotes set aside, each pair of quotes left is
        # one literal.
        string(REPLACE "<backslash><backslash>" "<backslashes>" line "${line}")
        string(REPLACE "<backslash>\"" "<quote>" line "${line}")
        string(REPLACE "'\"'" "<quote>" line "${line}")
        string(REGEX MATCHALL "\"[^\"]*\"" literals "${line}")
        foreach(literal ${literals})
            # "name", "--name" or "--name=value"
            if(literal MATCHES "^\"--([a-z0-9-]+)(=[^\"]*)?\"$")
                set(name ${CMAKE_MATCH_1})
            elseif(literal MATCHES "^\"([a-z0-9-]+)\"$")
                set(name ${CMAKE_MATCH_1})
            else()
                continue()
            endif()
            if(NOT name IN_LIST names)
                continue()
            endif()
            if("${file}:${name}" IN_LIST not_options AND NOT literal MATCHES "^\"--")
                list(APPEND not_options_seen "${file}:${name}")
            else()
                list(APPEND faults "app/${file}:${number}: ${literal} is an option's name (take it from cli/optionnames.h)")
            endif()
        endforeach()
    endforeach()
endforeach()
# The list is what stands: an entry no file needs leaves it.
foreach(entry ${not_options})
    if(NOT entry IN_LIST not_options_seen)
        list(APPEND faults "app/${entry}: listed as a literal that is no option, and no longer written there: take it off the list")
    endif()
endforeach()
if(faults)
    list(JOIN faults "\n  " text)
    message(FATAL_ERROR "an option's name written outside app/cli/optionnames.h:\n  ${text}")
endif()
list(LENGTH files scanned)
message(STATUS "every option's name is written once (${named} names, ${scanned} files read)")
