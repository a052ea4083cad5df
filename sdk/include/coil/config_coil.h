// SPDX-License-Identifier: MIT
/*!
 * @file config_coil.h
 * @brief Platform macros of coil (the values OpenRTM-aist's build writes into its config_coil.h).
 */
#ifndef CONFIG_COIL_H
#define CONFIG_COIL_H

#if defined(__linux__)
#ifndef COIL_OS_LINUX
#define COIL_OS_LINUX TRUE
#endif
#elif defined(__APPLE__)
#ifndef COIL_OS_DARWIN
#define COIL_OS_DARWIN TRUE
#endif
#elif defined(__FreeBSD__)
#ifndef COIL_OS_FREEBSD
#define COIL_OS_FREEBSD TRUE
#endif
#elif defined(__QNX__)
#ifndef COIL_OS_QNX
#define COIL_OS_QNX TRUE
#endif
#endif

/*! Every coil of this SDK is the POSIX flavour. */
#define COIL_PLATFORM_POSIX 1
#define COIL_PLATFORM POSIX

/*! Version of the OpenRTM-aist coil API this SDK follows. */
#define COIL_VERSION "2.1.0"
#define COIL_MAJOR_VERSION 2
#define COIL_MINOR_VERSION 1
#define COIL_REVISION_NUM 0

/*!
 * Marks functions whose result is their only effect. OpenRTM-aist 1.x changed some strings in
 * place (coil::toLower(str);) where 2.x returns the changed copy; the compiler then points at
 * 1.x-style calls that would silently do nothing.
 */
#if defined(__GNUC__) || defined(__clang__)
#define COIL_WARN_UNUSED_RESULT __attribute__((warn_unused_result))
#else
#define COIL_WARN_UNUSED_RESULT
#endif

#endif // CONFIG_COIL_H
