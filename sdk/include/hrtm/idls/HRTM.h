// SPDX-License-Identifier: MIT
// HRTM's own IDL types: OpenRTM-aist 2.1 ships none, so this header only has to exist.
