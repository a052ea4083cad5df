// SPDX-License-Identifier: MIT
/*!
 * @file UUID.h
 * @brief coil::UUID: random (version 4) UUIDs as text.
 */
#ifndef COIL_UUID_H
#define COIL_UUID_H

#include <coil/config_coil.h>

#include <cstring>

// OpenRTM-aist's UUID.h includes libuuid's header; where it is installed, so does this one, and
// coil::UUID can then be made from a libuuid uuid_t.
#if defined(__has_include)
#if __has_include(<uuid/uuid.h>)
#include <uuid/uuid.h>
#define COIL_UUID_HAS_LIBUUID 1
#endif
#endif

namespace coil {
/*! A random UUID (RFC 4122 version 4). */
class UUID
{
public:
    /*! A new random UUID. */
    UUID();
#ifdef COIL_UUID_HAS_LIBUUID
    /*! The UUID held in @p uuid. */
    explicit UUID(uuid_t *uuid)
        : m_text()
    {
        std::memcpy(m_bytes, *uuid, sizeof(m_bytes));
    }
#endif
    /*! The UUID as 36 characters, e.g. "1b4e28ba-2fa1-41d2-883f-0016d3cca427". */
    const char *to_string();

private:
    unsigned char m_bytes[16];
    char m_text[37];
};

/*!
 * The UUID factory, usable both ways OpenRTM-aist had it: 2.x calls
 * coil::UUID_Generator::generateUUID(n, h), 1.x made an object and called init() first.
 */
class UUID_Generator
{
public:
    UUID_Generator() { }
    /*! Nothing to prepare (kept for 1.x code). */
    void init() { }
    /*! A new random UUID, allocated with new; the arguments are ignored. */
    static UUID *generateUUID(int n, int h);
};
} // namespace coil

#endif // COIL_UUID_H
