# SPDX-License-Identifier: MIT
# Component packages (rtctl package) and Debian repositories of them (rtctl repo) that apt-get reads.
rtstudio_add_test(tst_debnames SOURCES tst_debnames.cpp LIBS rtpackages)

rtstudio_add_test(tst_componentpackage SOURCES tst_componentpackage.cpp
    LIBS rtstudio_livetest rtstudio_rtctlrunner rtstudio_sdkproject)
rtstudio_uses_sdk_projects(tst_componentpackage)
set_tests_properties(tst_componentpackage PROPERTIES LABELS package TIMEOUT 600)

rtstudio_add_test(tst_componentrepository SOURCES tst_componentrepository.cpp LIBS rtstudio_rtctlrunner rtpackages)
add_dependencies(tst_componentrepository rtctl)
set_tests_properties(tst_componentrepository PROPERTIES LABELS package)

# The Builder's Package and Publish… (a generated project built against this tree's SDK).
rtstudio_add_test(tst_builderpackage SOURCES tst_builderpackage.cpp
    LIBS rtstudio_app rtstudio_rtctlrunner rtstudio_sdkproject)
rtstudio_uses_sdk_projects(tst_builderpackage)
set_tests_properties(tst_builderpackage PROPERTIES LABELS package TIMEOUT 600)

# The System Editor's Repository view over a component repository.
rtstudio_add_test(tst_serepositorypackages SOURCES tst_serepositorypackages.cpp
    LIBS rtsystemeditor rtstudio_rtctlrunner rtstudio_livetest)
add_dependencies(tst_serepositorypackages rtctl)
set_tests_properties(tst_serepositorypackages PROPERTIES LABELS package)

rtstudio_add_test(tst_packagestore SOURCES tst_packagestore.cpp LIBS rtpackageinstall)
set_tests_properties(tst_packagestore PROPERTIES LABELS package)

# rtctl node and rtmanager's package installer: installs without root, verified as apt does.
rtstudio_add_test(tst_managerinstall SOURCES tst_managerinstall.cpp
    LIBS rtstudio_livetest rtstudio_rtctlrunner rtstudio_sdkproject rtcorba)
rtstudio_uses_sdk_projects(tst_managerinstall)
set_tests_properties(tst_managerinstall PROPERTIES LABELS package TIMEOUT 600)

# rtctl deploy / undeploy: installs from a repository, restore and start as one transaction.
rtstudio_add_test(tst_deployinstall SOURCES tst_deployinstall.cpp tst_deploysupport.h
    LIBS rtstudio_app rtdeploy rtstudio_livetest rtstudio_rtctlrunner rtstudio_sdkproject rtcorba_stubs)
rtstudio_uses_sdk_projects(tst_deployinstall)
set_tests_properties(tst_deployinstall PROPERTIES LABELS package TIMEOUT 600)
