# SPDX-License-Identifier: MIT
# The two helpers of OpenRTP 2.0's cmake/utils.cmake that idl/ and src/ call.

# FILTER_LIST(<name of a list> <regex> <result>): the items of the list that match.
macro(FILTER_LIST _list _pattern _result)
  set(${_result})
  foreach(_item IN LISTS ${_list})
    if("${_item}" MATCHES "${_pattern}")
      list(APPEND ${_result} "${_item}")
    endif()
  endforeach()
endmacro(FILTER_LIST)

# MAP_ADD_STR(<name of a list> <prefix> <result>): every item with the prefix put before it.
macro(MAP_ADD_STR _list _prefix _result)
  set(${_result})
  foreach(_item IN LISTS ${_list})
    list(APPEND ${_result} "${_prefix}${_item}")
  endforeach()
endmacro(MAP_ADD_STR)
