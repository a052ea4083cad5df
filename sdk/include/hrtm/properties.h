// SPDX-License-Identifier: MIT
/*!
 * @file properties.h
 * @brief hrtm::utils::Properties: coil::Properties made from a component's spec array.
 */
#ifndef HRTM_PROPERTIES_H
#define HRTM_PROPERTIES_H

#include <coil/Properties.h>

#include <cstddef>
#include <limits>

namespace hrtm {
namespace utils {
/*! Properties, usually a component profile built from its `{"key", "value", …, ""}` spec. */
class Properties : public coil::Properties
{
public:
    explicit Properties();
    /*! The pairs of @p defaults, up to its empty-string end or @p num entries. */
    explicit Properties(const char *const defaults[], long num = std::numeric_limits<size_t>::max());
    ~Properties() override;
};
} // namespace utils
} // namespace hrtm

#endif // HRTM_PROPERTIES_H
