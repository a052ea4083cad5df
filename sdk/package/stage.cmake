# SPDX-License-Identifier: MIT
# Run at build time (cmake -P) by target rtsdk_stage: brings the build-tree prefix's headers up to date.
# Copies only what changed, so users' builds against the build tree recompile only after real edits, and
# removes staged headers whose source is gone.
#
#   RTSDK_SOURCE_INCLUDE     sdk/include (rtm/, coil/, hrtm/)
#   RTSDK_RUNTIME_HEADERS    the runtime's headers (manager/), included by rtm/*.h as <rtmruntime/…>
#   RTSDK_GENERATED_INCLUDE  configure-time headers (rtm/config_rtc.h, rtm/version.h, rtm/idl/*.h)
#   RTSDK_IDL_DIR            the bundled IDL files
#   RTSDK_OMNIIDL_DIR        omniidl's output for them (<Name>.hh)
#   RTSDK_PREFIX             the build-tree prefix
#   RTSDK_RTM_DIR            openrtm-2.1

cmake_minimum_required(VERSION 3.22)

function(rtsdk_copy from to)
    get_filename_component(folder "${to}" DIRECTORY)
    file(MAKE_DIRECTORY "${folder}")
    file(COPY_FILE "${from}" "${to}" ONLY_IF_DIFFERENT)
endfunction()

# Mirrors the headers under from/ into to/ (relative paths kept; only from/'s own with FLAT), removing
# staged ones whose source is gone.
function(rtsdk_mirror from to)
    cmake_parse_arguments(ARG "FLAT" "" "" ${ARGN})
    if(ARG_FLAT)
        file(GLOB sources RELATIVE "${from}" "${from}/*.h")
    else()
        file(GLOB_RECURSE sources RELATIVE "${from}" "${from}/*.h")
    endif()
    foreach(relative IN LISTS sources)
        rtsdk_copy("${from}/${relative}" "${to}/${relative}")
    endforeach()
    file(GLOB_RECURSE staged RELATIVE "${to}" "${to}/*.h")
    foreach(relative IN LISTS staged)
        if(NOT relative IN_LIST sources)
            file(REMOVE "${to}/${relative}")
        endif()
    endforeach()
endfunction()

set(include "${RTSDK_PREFIX}/include")
set(rtm "${include}/${RTSDK_RTM_DIR}/rtm")

file(GLOB_RECURSE generated RELATIVE "${RTSDK_GENERATED_INCLUDE}/rtm" "${RTSDK_GENERATED_INCLUDE}/rtm/*.h")
file(MAKE_DIRECTORY "${rtm}/idl" "${rtm}/ext")
# rtm/idl and rtm/ext are the SDK's own folders: only the headers of rtm/ itself mirror the source.
file(GLOB own_headers RELATIVE "${RTSDK_SOURCE_INCLUDE}/rtm" "${RTSDK_SOURCE_INCLUDE}/rtm/*.h")
file(GLOB staged_headers RELATIVE "${rtm}" "${rtm}/*.h")
foreach(relative IN LISTS staged_headers)
    if(NOT relative IN_LIST own_headers AND NOT relative IN_LIST generated)
        file(REMOVE "${rtm}/${relative}")
    endif()
endforeach()
file(GLOB_RECURSE rtm_sources RELATIVE "${RTSDK_SOURCE_INCLUDE}/rtm" "${RTSDK_SOURCE_INCLUDE}/rtm/*.h")
foreach(relative IN LISTS rtm_sources)
    rtsdk_copy("${RTSDK_SOURCE_INCLUDE}/rtm/${relative}" "${rtm}/${relative}")
endforeach()
foreach(relative IN LISTS generated)
    rtsdk_copy("${RTSDK_GENERATED_INCLUDE}/rtm/${relative}" "${rtm}/${relative}")
endforeach()

file(GLOB idl_files "${RTSDK_IDL_DIR}/*.idl" "${RTSDK_OMNIIDL_DIR}/*.hh")
foreach(file IN LISTS idl_files)
    get_filename_component(name "${file}" NAME)
    rtsdk_copy("${file}" "${rtm}/idl/${name}")
endforeach()

rtsdk_mirror("${RTSDK_RUNTIME_HEADERS}" "${include}/${RTSDK_RTM_DIR}/rtmruntime" FLAT)
rtsdk_mirror("${RTSDK_SOURCE_INCLUDE}/hrtm" "${include}/${RTSDK_RTM_DIR}/hrtm")

foreach(coil coil-2.1 coil-2.0)
    file(MAKE_DIRECTORY "${include}/${coil}/coil")
    rtsdk_mirror("${RTSDK_SOURCE_INCLUDE}/coil" "${include}/${coil}/coil")
endforeach()
