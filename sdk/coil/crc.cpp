// SPDX-License-Identifier: MIT
#include <coil/crc.h>

namespace coil {
unsigned short crc16(const char *str, size_t len)
{
    unsigned int crc = 0xFFFF;
    for (size_t i = 0; str != nullptr && i < len; ++i) {
        crc ^= static_cast<unsigned int>(static_cast<unsigned char>(str[i])) << 8;
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc & 0x8000) ? ((crc << 1) ^ 0x1021) : (crc << 1);
        crc &= 0xFFFF;
    }
    return static_cast<unsigned short>(crc);
}

unsigned long crc32(const char *str, size_t len)
{
    unsigned long crc = 0xFFFFFFFFUL;
    for (size_t i = 0; str != nullptr && i < len; ++i) {
        crc ^= static_cast<unsigned char>(str[i]);
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc & 1) ? ((crc >> 1) ^ 0xEDB88320UL) : (crc >> 1);
    }
    return (crc ^ 0xFFFFFFFFUL) & 0xFFFFFFFFUL;
}
} // namespace coil
