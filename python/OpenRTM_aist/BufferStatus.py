# SPDX-License-Identifier: MIT
"""OpenRTM-aist's buffer status codes, with their names and values there."""

BUFFER_OK = 0
BUFFER_ERROR = 1
BUFFER_FULL = 2
BUFFER_EMPTY = 3
NOT_SUPPORTED = 4
TIMEOUT = 5
PRECONDITION_NOT_MET = 6
