// SPDX-License-Identifier: MIT
/*!
 * @file version.h
 * @brief The HRTM API version this SDK provides (the one OpenRTM-aist 2.1 ships).
 */
#ifndef HRTM_VERSION_H_
#define HRTM_VERSION_H_

#define HRTM_VERSION_MAJOR 0
#define HRTM_VERSION_MINOR 6
#define HRTM_VERSION_PATCH 13
#define HRTM_REVISION

#endif // HRTM_VERSION_H_
