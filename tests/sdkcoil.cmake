# SPDX-License-Identifier: MIT
# coil (sdk/include/coil, sdk/coil): OpenRTM-aist's utility library in the component SDK.

# The public coil headers must compile as C++11 with GNU extensions, as in components generated
# by OpenRTP 2.0 templates; building this object library is the check.
add_library(sdkcoil_cxx11 OBJECT sdk/coil_cxx11.cpp sdk/coil21_cxx11.cpp)
target_include_directories(sdkcoil_cxx11 PRIVATE ${PROJECT_SOURCE_DIR}/sdk/include)
set_target_properties(sdkcoil_cxx11 PROPERTIES
    CXX_STANDARD 11
    CXX_STANDARD_REQUIRED ON
    CXX_EXTENSIONS ON
    AUTOMOC OFF)

rtstudio_add_test(tst_sdkcoil SOURCES tst_sdkcoil.cpp LIBS rtsdk)
add_dependencies(tst_sdkcoil sdkcoil_cxx11)
