#!/bin/sh
# Runs DocumentedCompComp with OpenRTM-aist-Java's jars (RTM_JAVA_ROOT) on the class path.
cd "$(dirname "$0")" || exit 1
exec java -classpath "bin:${RTM_JAVA_ROOT}/jar/*" DocumentedCompComp "$@"
