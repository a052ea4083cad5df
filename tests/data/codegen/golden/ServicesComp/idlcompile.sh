#!/bin/sh
# Compiles the IDL files of ServicesComp into Python stubs and skeletons with omniidl.
# Set RTM_IDL_DIR to OpenRTM-aist's IDL folder when the project IDL includes its files.
cd "$(dirname "$0")" || exit 1
omniidl -bpython -Iidl ${RTM_IDL_DIR:+-I"$RTM_IDL_DIR"} "idl/Robotics.idl" || exit 1
exit 0
