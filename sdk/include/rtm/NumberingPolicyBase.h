// SPDX-License-Identifier: MIT
// How instance numbers are given to new components.
#ifndef RTC_NUMBERINGPOLICYBASE_H
#define RTC_NUMBERINGPOLICYBASE_H

#include <string>
#include <vector>

namespace RTM
{
/// Gives each new object a number (as text), and takes it back when the object goes.
class NumberingPolicyBase
{
public:
    /// Thrown by policies asked about an object they do not know.
    struct ObjectNotFound
    {
    };
    virtual ~NumberingPolicyBase() = default;
    /// The number for @p obj (an RTC::RTObject_impl* for the manager's policies).
    virtual std::string onCreate(void *obj) = 0;
    virtual void onDelete(void *obj) = 0;
};

/**
 * The numbering policies by name — the values of `manager.components.naming_policy`:
 * `process_unique`, `node_unique`, `ns_unique` and what programs add (OpenRTM's
 * coil::GlobalFactory of them). The runtime's manager itself numbers as process_unique does.
 */
class NumberingPolicyFactory
{
public:
    using Creator = NumberingPolicyBase *(*)();
    using Destructor = void (*)(NumberingPolicyBase *);
    enum ReturnCode
    {
        FACTORY_OK,
        FACTORY_ERROR,
        ALREADY_EXISTS,
        NOT_FOUND,
        INVALID_ARG,
        UNKNOWN_ERROR
    };

    static NumberingPolicyFactory &instance();
    bool hasFactory(const std::string &id);
    std::vector<std::string> getIdentifiers();
    ReturnCode addFactory(const std::string &id, Creator creator, Destructor destructor);
    ReturnCode removeFactory(const std::string &id);
    /// A new policy @p id; null (and a message naming the known ones) when unknown.
    NumberingPolicyBase *createObject(const std::string &id);
    ReturnCode deleteObject(NumberingPolicyBase *&obj);

private:
    NumberingPolicyFactory();
    struct Private;
    Private *d;
};
} // namespace RTM

#endif // RTC_NUMBERINGPOLICYBASE_H
