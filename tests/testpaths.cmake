# SPDX-License-Identifier: MIT
# The paths the test programs are told (target_compile_definitions NAME="path") name the checkout,
# and a definition is part of every compile command: in another clone (CI's) not one test object
# would come from ccache. rtstudio_resolve_test_paths() rewrites, on every target of the calling
# folder, each definition whose value lies in the build tree or in the sources, or is the file or
# folder of a target built here, into a call of common/testpaths.h with a relative path, resolved
# when the test runs. The definitions then name a QString, not a string literal.

# Names whose value is a path even when configured outside the sources (then kept as it is).
set(RTSTUDIO_TEST_PATH_NAMES RTSTUDIO_CONFORMANCE_DIR)

# OUT: the C++ expression for definition NAME with VALUE, or empty when it is not a path of ours.
function(rtstudio_test_path_expression out name value)
    set(expression "")
    if(value MATCHES "^\\$<TARGET_FILE(_DIR)?:([^>]+)>$")
        get_target_property(imported ${CMAKE_MATCH_2} IMPORTED)
        if(NOT imported)
            set(expression
                "TestPaths::build(\"$<PATH:RELATIVE_PATH,${value},${CMAKE_BINARY_DIR}>\")")
        endif()
    elseif(IS_ABSOLUTE "${value}")
        cmake_path(IS_PREFIX CMAKE_BINARY_DIR "${value}" NORMALIZE in_build)
        cmake_path(IS_PREFIX CMAKE_SOURCE_DIR "${value}" NORMALIZE in_source)
        string(FIND "${value}" "${CMAKE_SOURCE_DIR}/" from_source)
        if(in_build)
            file(RELATIVE_PATH relative "${CMAKE_BINARY_DIR}" "${value}")
            set(expression "TestPaths::build(\"${relative}\")")
        elseif(in_source OR from_source EQUAL 0)
            file(RELATIVE_PATH relative "${CMAKE_SOURCE_DIR}" "${value}")
            set(expression "TestPaths::source(\"${relative}\")")
        elseif(name IN_LIST RTSTUDIO_TEST_PATH_NAMES)
            set(expression "QStringLiteral(\"${value}\")")
        endif()
    endif()
    set(${out} "${expression}" PARENT_SCOPE)
endfunction()

function(rtstudio_resolve_test_paths)
    get_directory_property(targets BUILDSYSTEM_TARGETS)
    foreach(target IN LISTS targets)
        get_target_property(type ${target} TYPE)
        if(type STREQUAL "UTILITY" OR type STREQUAL "INTERFACE_LIBRARY")
            continue()
        endif()
        get_target_property(definitions ${target} COMPILE_DEFINITIONS)
        if(NOT definitions)
            continue()
        endif()
        set(rewritten "")
        set(changed FALSE)
        foreach(definition IN LISTS definitions)
            if(definition MATCHES "^([A-Za-z0-9_]+)=\"(.*)\"$")
                set(name "${CMAKE_MATCH_1}")
                rtstudio_test_path_expression(expression ${name} "${CMAKE_MATCH_2}")
                if(expression)
                    set(definition "${name}=${expression}")
                    set(changed TRUE)
                endif()
            endif()
            list(APPEND rewritten "${definition}")
        endforeach()
        if(changed)
            set_target_properties(${target} PROPERTIES COMPILE_DEFINITIONS "${rewritten}")
            target_compile_options(${target} PRIVATE "SHELL:-include testpaths.h")
            target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/tests/common)
        endif()
    endforeach()
endfunction()
