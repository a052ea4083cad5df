// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <iterator>

namespace RtStudio {

/// The IDL name of an RTC::ReturnCode_t value (`RTC_OK` … `PRECONDITION_NOT_MET`); null for a value
/// the IDL does not define (a peer may send any number).
inline const char *returnCodeName(long code)
{
    static const char *const names[] = {"RTC_OK",           "RTC_ERROR", "BAD_PARAMETER", "UNSUPPORTED",
                                        "OUT_OF_RESOURCES", "PRECONDITION_NOT_MET"};
    return code >= 0 && static_cast<std::size_t>(code) < std::size(names) ? names[code] : nullptr;
}

} // namespace RtStudio
