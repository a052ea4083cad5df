// SPDX-License-Identifier: MIT
/*!
 * @file Singleton.h
 * @brief coil::Singleton: one lazily created, thread-safe instance of a class.
 */
#ifndef COIL_SINGLETON_H
#define COIL_SINGLETON_H

#include <mutex>

namespace coil {
/*!
 * Derive as `class X : public coil::Singleton<X>` (with `friend class coil::Singleton<X>;`
 * when X's constructor is private) and use X::instance(). The instance is created on first
 * use, by one thread only, and lives until the program ends.
 */
template<class SingletonClass> class Singleton
{
public:
    typedef SingletonClass *SingletonClassPtr;

    /*!
     * Holds an object and deletes it when destroyed (OpenRTM-aist keeps its instances in one;
     * instance() here never deletes its object, so that it outlives every static user).
     */
    struct Container
    {
        SingletonClass *x;
        ~Container() { delete x; }
    };

    /*! The instance, created on the first call. */
    static SingletonClass &instance()
    {
        // C++11 initialises function statics exactly once, even under concurrent calls.
        static SingletonClass *const object = new SingletonClass();
        return *object;
    }

protected:
    Singleton() { }
    ~Singleton() { }

private:
    Singleton(const Singleton &);
    Singleton &operator=(const Singleton &);
};
} // namespace coil

#endif // COIL_SINGLETON_H
