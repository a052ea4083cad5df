// SPDX-License-Identifier: MIT
/*!
 * @file crc.h
 * @brief CRC-16 and CRC-32 checksums.
 */
#ifndef COIL_CRC_H
#define COIL_CRC_H

#include <cstddef>
#include <sys/types.h>

namespace coil {
/*! CRC-16/CCITT (polynomial 0x1021, initial value 0xFFFF, no reflection, no final XOR). */
unsigned short crc16(const char *str, size_t len);
/*! CRC-32 as in zlib and PNG (reflected polynomial 0xEDB88320, initial and final XOR ~0). */
unsigned long crc32(const char *str, size_t len);
} // namespace coil

#endif // COIL_CRC_H
