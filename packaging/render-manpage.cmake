# SPDX-License-Identifier: GPL-3.0-or-later
# cmake -DGROFF=… -DPAGE=… -P render-manpage.cmake: renders a manual page as
# man(1) would and fails on any warning groff prints (-ww: all of them).
execute_process(COMMAND ${GROFF} -man -Tutf8 -ww -z ${PAGE}
                RESULT_VARIABLE status ERROR_VARIABLE warnings)
if(NOT status EQUAL 0 OR NOT warnings STREQUAL "")
    message(FATAL_ERROR "${PAGE}: groff exit ${status}:\n${warnings}")
endif()
execute_process(COMMAND ${GROFF} -man -Tutf8 ${PAGE} OUTPUT_VARIABLE text)
string(LENGTH "${text}" length)
if(length LESS 500)
    message(FATAL_ERROR "${PAGE}: rendered to only ${length} characters")
endif()
message(STATUS "${PAGE}: ${length} characters, no warnings")
