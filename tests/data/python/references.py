#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Object references inside data types: None when nil, as omniORBpy has them; a reference received
# in a sample is kept as its IOR and sent on as it came. Exits non-zero on the first failure.

import _rtstudio
import _rtstudio_interfaces
import OpenRTM_aist
import RTC


def main():
    profile = OpenRTM_aist.instantiateDataType(RTC.PortProfile)
    assert profile.port_ref is None and profile.owner is None
    profile.name = "in"
    # name "in", no interfaces, a nil port_ref (empty type id, no profiles), no connectors, nil owner, no properties.
    assert _rtstudio.cdr_encode(profile).hex() == (
        "03000000696e0000" "00000000" "0100000000000000" "00000000" "00000000" "0100000000000000" "00000000"
        "00000000"), _rtstudio.cdr_encode(profile).hex()
    held = _rtstudio_interfaces.ObjectReference("IDL:omg.org/RTC/RTObject:1.0", [(0, bytes(range(7)))])
    profile.owner = held
    for little in (True, False):
        back = _rtstudio.cdr_decode(profile._NP_RepositoryId, _rtstudio.cdr_encode(profile, little), little)
        assert back == profile and back.owner == held, back
    try:
        profile.owner = object()
        _rtstudio.cdr_encode(profile)
        raise AssertionError("a value that is no reference was sent")
    except TypeError as error:
        assert "owner" in str(error), error
    print("references: ok")


if __name__ == "__main__":
    main()
