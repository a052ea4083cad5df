// SPDX-License-Identifier: MIT
#include <coil/DynamicLib.h>

namespace coil {
DynamicLib::DynamicLib(int close_handle_on_destruction)
    : m_mode(COIL_DEFAULT_DYNLIB_MODE)
    , m_closeflag(close_handle_on_destruction)
    , m_handle(nullptr)
{ }

DynamicLib::DynamicLib(const char *dynlib_name, int open_mode, int close_handle_on_destruction)
    : m_mode(open_mode)
    , m_closeflag(close_handle_on_destruction)
    , m_handle(nullptr)
{
    DynamicLib::open(dynlib_name, open_mode, close_handle_on_destruction);
}

DynamicLib::~DynamicLib()
{
    if (m_closeflag != 0)
        DynamicLib::close();
}

DynamicLib::DynamicLib(const DynamicLib &rhs)
    : m_mode(rhs.m_mode)
    , m_closeflag(rhs.m_closeflag)
    , m_handle(nullptr)
{
    if (!rhs.m_name.empty())
        DynamicLib::open(rhs.m_name.c_str(), rhs.m_mode, rhs.m_closeflag);
}

DynamicLib &DynamicLib::operator=(const DynamicLib &rhs)
{
    if (this != &rhs) {
        DynamicLib copy(rhs);
        std::swap(m_name, copy.m_name);
        std::swap(m_mode, copy.m_mode);
        std::swap(m_closeflag, copy.m_closeflag);
        std::swap(m_handle, copy.m_handle);
    }
    return *this;
}

int DynamicLib::open(const char *dll_name, int open_mode, int close_handle_on_destruction)
{
    if (dll_name == nullptr)
        return -1;
    void *handle = ::dlopen(dll_name, open_mode);
    if (handle == nullptr)
        return -1;
    if (m_handle != nullptr)
        ::dlclose(m_handle);
    m_handle = handle;
    m_name = dll_name;
    m_mode = open_mode;
    m_closeflag = close_handle_on_destruction;
    return 0;
}

int DynamicLib::close()
{
    if (m_handle == nullptr)
        return -1;
    const int result = ::dlclose(m_handle);
    m_handle = nullptr;
    m_name.clear();
    return result == 0 ? 0 : -1;
}

void *DynamicLib::symbol(const char *symbol_name)
{
    if (m_handle == nullptr || symbol_name == nullptr)
        return nullptr;
    return ::dlsym(m_handle, symbol_name);
}

const char *DynamicLib::error()
{
    return ::dlerror();
}
} // namespace coil

extern "C" int ForExternTest(void)
{
    return coil::DynamicLib::ForExternTest();
}
