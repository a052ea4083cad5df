// SPDX-License-Identifier: MIT
// Execution context factories, as a module or program registers context types with the manager.
#ifndef RTC_ECFACTORY_H
#define RTC_ECFACTORY_H

#include <rtm/ExecutionContextBase.h>

#include <condition_variable>
#include <string>

namespace RTC
{
/// Makes a new execution context object.
using ECNewFunc = ExecutionContextBase *(*)();
/// Gives an execution context object back.
using ECDeleteFunc = void (*)(ExecutionContextBase *);

/// The creation function of context type @p T_New.
template <class T_New>
ExecutionContextBase *ECCreate()
{
    return new T_New();
}

/// The destruction function of context type @p T_Delete.
template <class T_Delete>
void ECDelete(ExecutionContextBase *ec)
{
    delete ec;
}

/// A named way to make and give back execution contexts.
class ECFactoryBase
{
public:
    virtual ~ECFactoryBase() = default;
    virtual const char *name() = 0;
    virtual ExecutionContextBase *create() = 0;
    virtual void destroy(ExecutionContextBase *comp) = 0;
};

/// An ECFactoryBase over a pair of creation and destruction functions.
class ECFactoryCXX : public ECFactoryBase
{
public:
    ECFactoryCXX(const char *name, ECNewFunc new_func, ECDeleteFunc delete_func);
    ~ECFactoryCXX() override;
    const char *name() override;
    ExecutionContextBase *create() override;
    void destroy(ExecutionContextBase *ec) override;

protected:
    std::string m_name;
    ECNewFunc m_New;
    ECDeleteFunc m_Delete;
};
} // namespace RTC

#endif // RTC_ECFACTORY_H
