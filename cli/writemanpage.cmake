# SPDX-License-Identifier: MIT
# cmake -DPROGRAM=… -DOUTPUT=… -P writemanpage.cmake: OUTPUT becomes what `PROGRAM --man` prints,
# written whole or not at all.
execute_process(COMMAND "${PROGRAM}" --man OUTPUT_FILE "${OUTPUT}.tmp" RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    file(REMOVE "${OUTPUT}.tmp")
    message(FATAL_ERROR "${PROGRAM} --man failed: ${result}")
endif()
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
