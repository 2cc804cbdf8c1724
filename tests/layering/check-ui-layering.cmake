# SPDX-License-Identifier: GPL-3.0-or-later
# The window's widgets are laid out by feature (ui/rotor, ui/tracking, ...),
# beside ui/widgets, which knows no feature, and the window at the top of
# ui/. A folder stays one feature only while it does not reach into the
# others: the build cannot hold this, every folder's headers sit under the
# one include root (ui/). This check reads every #include in ui/ and fails
# naming the file and the include that breaks one of three rules:
#  - ui/widgets includes no feature folder's header and no header of the
#    core's station parts (session/, station/, tracking/, radio/, ...):
#    a widget that knows no feature can be used by every one;
#  - a feature folder includes its own headers, ui/widgets, the top of ui/
#    and the core; another feature's header only where the pair is listed
#    below, with why (debt: the shared piece belongs in ui/widgets);
#  - a widget that reaches the station's parts themselves (the session, the
#    Station, the pass runner, a radio link, a remote station) is one of the
#    files listed below, the debt the station's face will pay off: it will
#    hand the widgets what they show and take what they ask. No other file
#    may start to.
# The top of ui/ (the main window) may include every folder.
#
#   cmake -DROOT=path/to/source -P check-ui-layering.cmake

cmake_minimum_required(VERSION 3.25)

set(features rotor tracking history radio telemetry remote wizard)
# The core's areas of the station's parts, which ui/widgets never includes.
set(part_areas session station tracking radio remote bridge schedule records console tuning)
# A station part's header: what the station's face will stand between.
set(part_header "^(session/.*|station/.*|tracking/passrunner[.]h|radio/[^/]*link[^/]*[.]h|remote/remotestation[.]h)$")

# One feature's header in another's: debt_<from>_<to> says why.
set(debt_remote_rotor "the remote window and its tile show the polar plot (rotor/polarplotwidget.h) and its pass")
set(debt_tracking_rotor "the tracking panel hands the polar plot the pass it draws (rotor/passoverlay.h)")
set(debt_telemetry_tracking "the charts mark a rehearsal as the status bar does (tracking/rehearsalmarker.h)")

# The files (under ui/) that include a station part's header today.
set(part_users
    # the window and what every page shares
    stationwindow.h stationwindow.cpp stationwindow_local.cpp stationwindow_remote.cpp operatoractions.h eventlog.h stopbutton.h
    rotor/alignmentpanel.cpp rotor/configeditor.h rotor/connectionbar.h rotor/connectionbar.cpp
    rotor/rotorspanel.cpp rotor/rotortile.cpp rotor/trafficconsole.h
    tracking/timecontroller.cpp
    tracking/trackingpanel.h tracking/trackingpanel.cpp
    tracking/upcomingpanel.cpp
    history/historypanel.cpp
    radio/radiolinkbox.h radio/radiolinkbox.cpp radio/radiopanel.cpp radio/radiopassbandtuner.cpp
    radio/radioplanform.cpp radio/radioreadout.cpp radio/radiovfochoice.cpp
    telemetry/statuslanes.cpp telemetry/telemetryrecorder.h
    remote/remotebanner.cpp remote/remoteopener.cpp
    remote/stationnetworkwindow.cpp
    # the setup wizard talks to the controller's session itself
    wizard/calibrationpage.h wizard/connectpage.cpp wizard/directioncheck.h wizard/directioncheck.cpp
    wizard/identifypage.cpp wizard/mechanicspage.h wizard/mechanicspage.cpp wizard/parkpage.cpp
    wizard/setupwizard.cpp wizard/tuningpage.cpp)

file(GLOB_RECURSE files RELATIVE ${ROOT}/ui ${ROOT}/ui/*.h ${ROOT}/ui/*.cpp)
set(faults "")
set(checked 0)
set(part_users_seen "")
set(debts_seen "")
foreach(file ${files})
    string(REGEX MATCH "^[^/]+/" folder "${file}")
    string(REGEX REPLACE "/$" "" folder "${folder}")
    get_filename_component(dir ${file} DIRECTORY)
    if(folder STREQUAL "")
        set(folder top)
    elseif(NOT folder STREQUAL "widgets" AND NOT folder IN_LIST features)
        list(APPEND faults "ui/${file}: folder '${folder}' has no place in the rules (tests/layering/check-ui-layering.cmake)")
        continue()
    endif()
    file(STRINGS ${ROOT}/ui/${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    foreach(line ${includes})
        string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]*)\".*" "\\1" path "${line}")
        # Found as the compiler finds it: beside the file, then under ui/, then under core/.
        if(NOT dir STREQUAL "" AND EXISTS ${ROOT}/ui/${dir}/${path})
            set(used ${folder})
        elseif(EXISTS ${ROOT}/ui/${path})
            if(EXISTS ${ROOT}/core/${path})
                list(APPEND faults "ui/${file}: ${line} names a header under ui/ and one under core/ alike")
            endif()
            string(REGEX MATCH "^[^/]+/" used "${path}")
            string(REGEX REPLACE "/$" "" used "${used}")
            if(used STREQUAL "")
                set(used top)
            endif()
        elseif(EXISTS ${ROOT}/core/${path})
            string(REGEX MATCH "^[^/]+/" area "${path}")
            string(REGEX REPLACE "/$" "" area "${area}")
            if(folder STREQUAL "widgets" AND area IN_LIST part_areas)
                list(APPEND faults "ui/${file}: ${line} (ui/widgets knows no station part: core/${area})")
            endif()
            if(path MATCHES "${part_header}")
                list(APPEND part_users_seen ${file})
                if(NOT file IN_LIST part_users)
                    list(APPEND faults "ui/${file}: ${line} (a station part's header, and the file is not on the list of those that reach one)")
                endif()
            endif()
            continue()
        else()
            continue() # a generated file (*.moc), or Qt's
        endif()
        if(used STREQUAL folder OR used STREQUAL "widgets" OR folder STREQUAL "top")
            continue()
        endif()
        math(EXPR checked "${checked} + 1")
        if(folder STREQUAL "widgets" AND NOT used STREQUAL "top")
            list(APPEND faults "ui/${file}: ${line} (ui/widgets knows no feature: ${used})")
        elseif(NOT folder STREQUAL "widgets" AND NOT used STREQUAL "top")
            if(DEFINED debt_${folder}_${used})
                list(APPEND debts_seen debt_${folder}_${used})
            else()
                list(APPEND faults "ui/${file}: ${line} (${folder} may use its own folder, ui/widgets and the top of ui/, not ${used})")
            endif()
        endif()
    endforeach()
endforeach()
# The lists are the debt as it stands: what is paid off leaves them.
get_cmake_property(names VARIABLES)
list(FILTER names INCLUDE REGEX "^debt_")
foreach(name ${names})
    if(NOT name IN_LIST debts_seen)
        string(REGEX REPLACE "^debt_([a-z]+)_([a-z]+)$" "\\1 -> \\2" pair "${name}")
        list(APPEND faults "${pair}: listed as debt, and no file includes across it: take it off the list")
    endif()
endforeach()
foreach(file ${part_users})
    if(NOT file IN_LIST part_users_seen)
        list(APPEND faults "ui/${file}: listed as reaching a station part, and reaches none: take it off the list")
    endif()
endforeach()
if(faults)
    list(REMOVE_DUPLICATES faults)
    list(JOIN faults "\n  " text)
    message(FATAL_ERROR "ui/ includes across its folders' rules:\n  ${text}")
endif()
list(LENGTH files scanned)
list(REMOVE_DUPLICATES part_users_seen)
list(LENGTH part_users_seen debt)
message(STATUS "ui layering holds: ${scanned} files read, ${checked} includes across folders, ${debt} files reach a station part")
