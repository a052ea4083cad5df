// SPDX-License-Identifier: MIT
/*!
 * @file defs.h
 * @brief HRTM's portability macros (export markers, per-compiler statement filters).
 *
 * The SDK is one shared library on POSIX: the export markers are empty and no library is
 * pulled in by pragma.
 */
#ifndef HRTM_DEFS_H_
#define HRTM_DEFS_H_

#define EXPORT_DLL
#ifndef EXTERN
#define EXTERN extern
#endif

#ifndef __pragma
#define __pragma(x)
#endif

// The ORB in use (rtm/config_rtc.h says ORB_IS_OMNIORB), under the name HRTM code tests.
#if defined(ORB_IS_OMNIORB) && !defined(OMNIORB)
#define OMNIORB
#endif

/*! @p sentence only when compiling for Windows. */
#ifdef _WIN32
#define IF_WIN32(sentence) sentence
#else
#define IF_WIN32(sentence)
#endif

/*! @p sentence only with Microsoft's compiler. */
#ifdef _MSC_VER
#define IF_MSC_VER(sentence) sentence
#else
#define IF_MSC_VER(sentence)
#endif

/*! @p sentence only with GCC-compatible compilers. */
#ifdef __GNUC__
#define IF__GNUC__(sentence) sentence
#else
#define IF__GNUC__(sentence)
#endif

/*! @p sentence only with GCC-compatible C++ compilers. */
#ifdef __GNUG__
#define IF__GNUG__(sentence) sentence
#else
#define IF__GNUG__(sentence)
#endif

/*! @p sentence only on Linux. */
#if defined(linux) || defined(__linux) || defined(__linux__)
#define IF__linux(sentence) sentence
#else
#define IF__linux(sentence)
#endif

/*! Declares, without defining, @p TypeName's copy constructor and assignment: no copies. */
#define DISALLOW_COPY_AND_ASSIGN(TypeName) \
    TypeName(const TypeName &);            \
    TypeName &operator=(const TypeName &)

#endif // HRTM_DEFS_H_
