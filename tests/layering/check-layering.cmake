# SPDX-License-Identifier: GPL-3.0-or-later
# The core's areas form layers; a file may include headers of its own area
# and of the areas below it, never above. The build alone cannot hold this:
# every area's headers sit under the one include root (core/). This check
# reads every #include "area/..." in core/ and fails naming the file and the
# include that crosses a layer upwards. (That the core never includes a
# widget header is held by the build: slewcore does not link Qt Widgets.)
#
#   cmake -DCORE=path/to/core -P check-layering.cmake

cmake_minimum_required(VERSION 3.25)

# input: numbers, files and text from outside, made safe; below everything.
set(allowed_input "")
set(allowed_protocol "input")
set(allowed_transport "input")
set(allowed_sky "input")
set(allowed_model "protocol;input")
set(allowed_session "model;protocol;transport;input")
set(allowed_sim "model;protocol;transport;input")
set(allowed_tuning "session;model;protocol;transport;input")
set(allowed_bridge "session;model;protocol;transport;input")
set(allowed_console "radio;session;tuning;model;protocol;transport;input")
set(allowed_tracking "session;model;protocol;transport;sky;input")
# radio: links to the radio and the Doppler steering, beside the tracker.
set(allowed_radio "tracking;session;sky;model;protocol;transport;input")
# records: the pass records' database; made of values the station hands it.
set(allowed_records "input")
# face: what a face shows of a station and asks of it, as values (state,
# plan, schedule, telemetry, outcomes), below both kinds of station.
set(allowed_face "schedule;model;sky;input")
# remote: MQTT (the broker, the client, the messages) and the remote station a
# window shows; it knows values (positions, limits), never the Station, which
# sits above it and publishes itself through it (station/remoteoperation.h).
# A schedule is a value too: the remote one is the local one's.
set(allowed_remote "face;schedule;session;model;protocol;transport;sky;input")
set(allowed_schedule "tracking;sky;model;input")
# station: one ground station's parts and their rules; the faces (ui, app) sit on it.
set(allowed_station "face;schedule;records;remote;radio;bridge;tracking;session;sky;model;protocol;transport;input")
set(areas input protocol transport sky model session sim tuning bridge console tracking radio records schedule face remote station)

file(GLOB_RECURSE files RELATIVE ${CORE} ${CORE}/*.h ${CORE}/*.cpp)
set(faults "")
set(checked 0)
foreach(file ${files})
    string(REGEX MATCH "^[^/]+" area "${file}")
    if(area STREQUAL file)
        continue() # core/linkschemes.*: the one place that wires every area
    endif()
    if(NOT area IN_LIST areas)
        list(APPEND faults "${file}: area '${area}' has no place in the layers (tests/layering)")
        continue()
    endif()
    file(STRINGS ${CORE}/${file} includes REGEX "^#include \"[a-z]+/")
    foreach(line ${includes})
        string(REGEX REPLACE "^#include \"([a-z]+)/.*" "\\1" used "${line}")
        if(used STREQUAL area OR NOT used IN_LIST areas)
            continue()
        endif()
        math(EXPR checked "${checked} + 1")
        if(NOT used IN_LIST allowed_${area})
            list(APPEND faults "${file}: ${line} (${area} may use: ${allowed_${area}})")
        endif()
    endforeach()
endforeach()
if(faults)
    list(JOIN faults "\n  " text)
    message(FATAL_ERROR "includes that cross a layer upwards:\n  ${text}")
endif()
message(STATUS "core layering holds: ${checked} includes across areas checked")
