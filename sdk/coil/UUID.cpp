// SPDX-License-Identifier: MIT
#include <coil/UUID.h>

#include <cstdio>
#include <random>

namespace coil {
UUID::UUID()
    : m_text()
{
    static thread_local std::mt19937_64 engine {std::random_device {}()};
    std::uniform_int_distribution<int> byte(0, 255);
    for (unsigned char &b : m_bytes)
        b = static_cast<unsigned char>(byte(engine));
    m_bytes[6] = static_cast<unsigned char>((m_bytes[6] & 0x0f) | 0x40); // version 4
    m_bytes[8] = static_cast<unsigned char>((m_bytes[8] & 0x3f) | 0x80); // RFC 4122 variant
}

const char *UUID::to_string()
{
    char *out = m_text;
    for (int i = 0; i < 16; ++i) {
        if (i == 4 || i == 6 || i == 8 || i == 10)
            *out++ = '-';
        std::snprintf(out, 3, "%02x", m_bytes[i]);
        out += 2;
    }
    *out = '\0';
    return m_text;
}

UUID *UUID_Generator::generateUUID(int, int)
{
    return new UUID();
}
} // namespace coil
