# SPDX-License-Identifier: MIT
# HRTM's API (sdk/include/hrtm, sdk/hrtm): hrtm components made by hrtm::ComponentManager and run in
# one process, and hrtm::sc statecharts.
rtstudio_add_test(tst_sdkhrtm SOURCES tst_sdkhrtm.cpp LIBS rtsdk)
set_tests_properties(tst_sdkhrtm PROPERTIES LABELS sdk)

# The hrtm headers as C++11, the standard OpenRTP 2.0 projects build with.
add_library(sdkhrtm_cxx11 OBJECT sdk/hrtm_cxx11.cpp)
target_link_libraries(sdkhrtm_cxx11 PRIVATE rtsdk)
set_target_properties(sdkhrtm_cxx11 PROPERTIES CXX_STANDARD 11 CXX_EXTENSIONS ON AUTOMOC OFF)
add_dependencies(tst_sdkhrtm sdkhrtm_cxx11)
