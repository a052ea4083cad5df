// SPDX-License-Identifier: MIT
// The IDL type name and repository id of a C++ type generated from IDL, read from the TypeCode
// that its CORBA::Any insertion carries (e.g. "TimedLong", "IDL:RTC/TimedLong:1.0").
#ifndef RTC_TYPENAME_H
#define RTC_TYPENAME_H

#include <rtm/RTC.h>

#include <iostream>

namespace CORBA_Util
{
/// Names a type only when T has `static T::_ptr_type _nil()` (an IDL interface type).
template <class T, typename T::_ptr_type (*)(void)>
struct has_nil_helper
{
    using type = void;
};

/// false, unless the specialisation below matches (T has _nil()).
template <class T, class U = void>
struct has_nil_impl
{
    static const bool value = false;
};

template <class T>
struct has_nil_impl<T, typename has_nil_helper<T, &T::_nil>::type>
{
    static const bool value = true;
};

/// Whether T is an IDL interface type: those have a static T::_nil() returning T::_ptr_type.
template <class T>
struct has_nil : has_nil_impl<T>
{
};

/// Whether T is a CORBA object (interface) type rather than a data type.
template <typename T>
struct is_corba_object
{
    static const bool value = has_nil<T>::value;
};

/// TypeCode facts of T; `cond` tells whether T is an interface type.
template <bool cond, class T>
class typecode;

template <class T>
class typecode<true, T>
{
public:
    static const char *id() { return sample()->id(); }
    static const char *name() { return sample()->name(); }

private:
    // The TypeCodes of generated types are static objects of the stubs, so the pointers
    // id() and name() hand out stay valid after the Any is gone.
    static CORBA::TypeCode_ptr sample()
    {
        CORBA::Any any;
        typename T::_ptr_type nil = T::_nil();
        any <<= nil;
        CORBA::TypeCode_var type = any.type();
        return type.in();
    }
};

template <class T>
class typecode<false, T>
{
public:
    static const char *id() { return sample()->id(); }
    static const char *name() { return sample()->name(); }

private:
    static CORBA::TypeCode_ptr sample()
    {
        CORBA::Any any;
        T value = T();
        any <<= value;
        CORBA::TypeCode_var type = any.type();
        return type.in();
    }
};

/// The IDL name of T ("TimedLong", "RTObject").
template <class T>
const char *toTypename()
{
    return typecode<is_corba_object<T>::value, T>::name();
}
/// The IDL name of the data type T.
template <class T>
const char *toTypenameOfStruct()
{
    return typecode<false, T>::name();
}
/// The IDL name of the interface type T.
template <class T>
const char *toTypenameOfObject()
{
    return typecode<true, T>::name();
}
/// The repository id of T ("IDL:RTC/TimedLong:1.0").
template <class T>
const char *toRepositoryId()
{
    return typecode<is_corba_object<T>::value, T>::id();
}
/// The repository id of the data type T.
template <class T>
const char *toRepositoryIdOfStruct()
{
    return typecode<false, T>::id();
}
/// The repository id of the interface type T.
template <class T>
const char *toRepositoryIdOfObject()
{
    return typecode<true, T>::id();
}
} // namespace CORBA_Util

/// The pre-1.2 global name; prints that it is obsolete, as OpenRTM-aist does.
template <class T>
const char *toTypename()
{
    std::cerr << "toTypename() is obsolete. Please use CORBA_Util::toTypename() instead." << std::endl;
    return CORBA_Util::toTypename<T>();
}

#endif // RTC_TYPENAME_H
