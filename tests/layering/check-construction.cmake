# SPDX-License-Identifier: GPL-3.0-or-later
# The window and the programs are faces of a Station (core/station): they
# get the station's parts from it and make none of their own, so a rule
# about how the parts work together is written once. This check reads every
# source under ui/ and app/ and fails naming each place that makes one of
# the core's station parts itself: `new T(`, `make_unique<T>`,
# `make_shared<T>`, or a variable `T name;` / `T name(...)` / `T name{...}`,
# or that calls a factory of one (a radio link from its URI).
# slewctl is one conversation with one controller, or one radio, and keeps
# its bare session or radio link; slew --pass-report reads a records file.
#
#   cmake -DROOT=path/to/source -P check-construction.cmake

cmake_minimum_required(VERSION 3.25)

set(parts RotatorSession RotctldServer PassRunner Tracker AlarmMonitor ElementSetSources ControllerRotors
          SharedLine StationClock SimulatorPace MoveWatch ConsoleRunner TransponderSources
          DopplerRadio DopplerSteering RadioLink RigctldRadioLink HamlibRadioLink ControllerRadioLink
          PassRecordStore PassRecorder
          RemoteOperation StatePublisher PlanPublisher RemoteCommands RemoteJog MqttClient)
# Functions that make a part; the part each makes.
set(factories "makeRadioLink=RadioLink")
# file (relative to ROOT) = the parts it may make
set(allowed_app/slewctl_main.cpp "RotatorSession;ConsoleRunner;RadioLink")
# slew --pass-report reads the pass records, as slewctl reads a controller:
# no station, only the file, opened to read.
set(allowed_app/slew_passreport.cpp "PassRecordStore")

file(GLOB_RECURSE files RELATIVE ${ROOT} ${ROOT}/ui/*.h ${ROOT}/ui/*.cpp ${ROOT}/app/*.h ${ROOT}/app/*.cpp)
set(faults "")
list(LENGTH files scanned)
foreach(file ${files})
    file(READ ${ROOT}/${file} text)
    # Comments say what things are; they make nothing.
    string(REGEX REPLACE "//[^\n]*" "" text "${text}")
    foreach(part ${parts})
        if(part IN_LIST allowed_${file})
            continue()
        endif()
        set(q "(slew::)?([a-z]+::)?")
        if(text MATCHES "new ${q}${part}[ ({;]"
           OR text MATCHES "make_(unique|shared)<${q}${part}>"
           OR text MATCHES "(^|[\n;{}(])[ \t]*(const[ \t]+)?${q}${part}[ \t]+[a-zA-Z_][a-zA-Z0-9_]*[ \t]*[;({]")
            list(APPEND faults "${file}: makes a ${part}, where it should take the Station's")
        endif()
    endforeach()
    foreach(factory ${factories})
        string(REPLACE "=" ";" pair "${factory}")
        list(GET pair 0 function)
        list(GET pair 1 part)
        if(NOT part IN_LIST allowed_${file} AND text MATCHES "${function}[ \t]*\\(")
            list(APPEND faults "${file}: makes a ${part} (${function}), where it should take the Station's")
        endif()
    endforeach()
endforeach()
if(faults)
    list(JOIN faults "\n  " text)
    message(FATAL_ERROR "station parts made outside the Station:\n  ${text}")
endif()
message(STATUS "no station part is made in ui/ or app/ (${scanned} files read)")
