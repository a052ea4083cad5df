// SPDX-License-Identifier: MIT
/*!
 * @file NonCopyable.h
 * @brief Base classes that forbid copying their subclasses.
 */
#ifndef COIL_NONCOPYABLE_H
#define COIL_NONCOPYABLE_H

namespace coil {
/*! Derive from this to make a class non-copyable. */
class NonCopyable
{
protected:
    NonCopyable() { }
    ~NonCopyable() { }

private:
    NonCopyable(const NonCopyable &);
    NonCopyable &operator=(const NonCopyable &);
};

/*! The same for class @p T, as a per-class base (no shared base between unrelated classes). */
template<class T> class NonCopyableCRTP
{
protected:
    NonCopyableCRTP() { }
    ~NonCopyableCRTP() { }

private:
    NonCopyableCRTP(const NonCopyableCRTP &);
    T &operator=(const T &);
};
} // namespace coil

#endif // COIL_NONCOPYABLE_H
