// SPDX-License-Identifier: MIT
#include <hrtm/properties.h>

namespace hrtm {
namespace utils {
Properties::Properties()
    : coil::Properties("", "")
{ }

Properties::Properties(const char *const defaults[], long num)
    // A negative count (the default, converted) means "up to the end marker".
    : coil::Properties(defaults, num < 0 ? std::numeric_limits<size_t>::max() : static_cast<size_t>(num))
{ }

Properties::~Properties() = default;
} // namespace utils
} // namespace hrtm
