# SPDX-License-Identifier: MIT
# cmake -DREADELF=… -DFILES="a;b;…" -P runpath.cmake
# Each program or library the project installs must look for libraries only where it looks once
# installed: no empty entry in its search path (the dynamic loader takes one for the working
# directory) and no absolute folder (that would be the build tree's).
foreach(file IN LISTS FILES)
    execute_process(COMMAND "${READELF}" -d "${file}" OUTPUT_VARIABLE dynamic RESULT_VARIABLE code)
    if(NOT code EQUAL 0)
        message(FATAL_ERROR "${file}: ${READELF} failed (${code})")
    endif()
    string(REGEX MATCHALL "\\((RPATH|RUNPATH)\\)[^\n]*\\[[^]\n]*\\]" entries "${dynamic}")
    foreach(entry IN LISTS entries)
        string(REGEX REPLACE ".*\\[(.*)\\]" "\\1" path "${entry}")
        message(STATUS "${file}: ${path}")
        if(path STREQUAL "" OR path MATCHES "(^:|::|:$)")
            message(FATAL_ERROR "${file}: search path '${path}' has an empty entry, read as the working directory")
        endif()
        if(path MATCHES "(^|:)/")
            message(FATAL_ERROR "${file}: search path '${path}' names an absolute folder")
        endif()
    endforeach()
endforeach()
