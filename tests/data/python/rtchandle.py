#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Uses OpenRTM-aist-Python's AutoTest/rtc_handle.py, unchanged from the corpus folder given, as its
# programs do: RtmEnv on a name server, NameSpace.list_obj() walking its contexts and making an
# RtcHandle per component, then the handle of COMPONENT (configuration read, activate, deactivate)
# and the module's NVList helpers. Prints what it finds, each line starting "rtchandle:".
#
#   rtchandle.py AUTOTEST_DIR NAME_SERVER COMPONENT

import sys


def main():
    autotest, name_server, component = sys.argv[1:4]
    sys.path.insert(0, autotest)
    import rtc_handle
    env = rtc_handle.RtmEnv(sys.argv[:1], [name_server])
    ns = env.name_space[name_server]
    ns.list_obj()
    print("rtchandle: handles", " ".join(sorted(ns.rtc_handles)))
    path = [name for name in ns.rtc_handles if name.endswith("/" + component)][0]
    handle = ns.rtc_handles[path]
    print("rtchandle: instance", handle.profile.instance_name, "ports", len(handle.port_refs))
    print("rtchandle: int_param", handle.conf_set_data["default"]["int_param"])
    print("rtchandle: activate", handle.activate())
    print("rtchandle: state", handle.execution_contexts[0].get_component_state(handle.rtc_ref))
    print("rtchandle: deactivate", handle.deactivate())
    print("rtchandle: by name", ns.get_object_by_name(path)._is_a("IDL:omg.org/RTC/RTObject:1.0"))
    print("rtchandle: nvlist", rtc_handle.nvlist2dict(rtc_handle.dict2nvlist({"a": "b", "n": 3})))
    # Its OpenRTM-aist 1.0 / 1.1 variant (AutoTestComposite.py's) imports omniORB.cdrMarshal too.
    import rtc_handle10_11
    print("rtchandle: rtc_handle10_11", rtc_handle10_11.RtcHandle.__name__)


if __name__ == "__main__":
    main()
