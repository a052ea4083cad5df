// SPDX-License-Identifier: MIT
/*!
 * @file DynamicLib.h
 * @brief coil::DynamicLib: loads a shared library and looks up its symbols.
 */
#ifndef COIL_DYNAMICLIB_H
#define COIL_DYNAMICLIB_H

#include <coil/config_coil.h>

#include <dlfcn.h>
#include <string>

/*! The dlopen() mode used when none is given. */
#define COIL_DEFAULT_DYNLIB_MODE RTLD_LAZY

extern "C" {
/*! coil::DynamicLib::ForExternTest() under a C name, for dlsym() checks on the library itself. */
int ForExternTest(void);
}

namespace coil {
/*! A handle on a shared library opened with dlopen(). */
class DynamicLib
{
public:
    /*! No library yet; with @p close_handle_on_destruction the destructor closes it. */
    explicit DynamicLib(int close_handle_on_destruction = 1);
    /*! Opens @p dynlib_name (check with symbol() or error() whether that worked). */
    DynamicLib(const char *dynlib_name, int open_mode = COIL_DEFAULT_DYNLIB_MODE,
               int close_handle_on_destruction = 1);
    virtual ~DynamicLib();
    /*! Opens the same library again (dlopen counts the references). */
    DynamicLib(const DynamicLib &rhs);
    DynamicLib &operator=(const DynamicLib &rhs);
    /*! Opens @p dll_name, closing a library opened before; 0 on success, -1 on failure. */
    virtual int open(const char *dll_name, int open_mode = COIL_DEFAULT_DYNLIB_MODE,
                     int close_handle_on_destruction = 1);
    /*! Closes the library; 0 on success, -1 if none was open or dlclose() failed. */
    virtual int close();
    /*! The address of @p symbol_name, or null. */
    void *symbol(const char *symbol_name);
    /*! The last dlopen/dlsym error text, or null. */
    static const char *error();
    /*! A fixed value (0xdeadbeef) that tests look up to check that a library loaded. */
    static int ForExternTest() { return static_cast<int>(0xdeadbeef); }

private:
    std::string m_name;
    int m_mode;
    int m_closeflag;
    void *m_handle;
};
} // namespace coil

#endif // COIL_DYNAMICLIB_H
