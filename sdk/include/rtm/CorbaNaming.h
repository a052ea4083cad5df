// SPDX-License-Identifier: MIT
// A client of a CORBA name service (CosNaming): binds, resolves, lists and removes entries by
// CosNaming::Name or by string name ("ctx.kind/obj.kind"), creating missing contexts on request.
#ifndef RTC_CORBANAMING_H
#define RTC_CORBANAMING_H

#include <rtm/RTC.h>

#include <map>
#include <string>
#include <vector>

namespace RTC
{
/**
 * The naming service at one address (OpenRTM-aist's RTC::CorbaNaming). Every operation is a remote
 * call on the root context and throws what the name service throws (CosNaming exceptions,
 * CORBA::SystemException).
 */
class CorbaNaming
{
public:
    /// Not connected yet: call init() before anything else.
    explicit CorbaNaming(CORBA::ORB_ptr orb);
    /// Connected to `name_server` ("host:port" or a corbaloc/corbaname URL).
    /// @throws std::bad_alloc when it names no naming context, as OpenRTM-aist does.
    CorbaNaming(CORBA::ORB_ptr orb, const char *name_server);
    virtual ~CorbaNaming();

    /// Connects to `name_server`. @throws std::bad_alloc when it names no naming context.
    void init(const char *name_server);
    /// Whether the root context still answers.
    bool isAlive();

    using SystemException = CORBA::SystemException;
    using NotFound = CosNaming::NamingContext::NotFound;
    using CannotProceed = CosNaming::NamingContext::CannotProceed;
    using InvalidName = CosNaming::NamingContext::InvalidName;
    using AlreadyBound = CosNaming::NamingContext::AlreadyBound;
    using NotEmpty = CosNaming::NamingContext::NotEmpty;
    using InvalidAddress = CosNaming::NamingContextExt::InvalidAddress;
    using ObjectList = std::vector<CORBA::Object_ptr>;

    /// Binds `obj` at `name`; with `force`, missing intermediate contexts are created.
    void bind(const CosNaming::Name &name, CORBA::Object_ptr obj, bool force = true);
    void bindByString(const char *string_name, CORBA::Object_ptr obj, bool force = true);
    /// Binds `obj` at `name` below `context`, creating or reusing each intermediate context.
    void bindRecursive(CosNaming::NamingContext_ptr context, const CosNaming::Name &name,
                       CORBA::Object_ptr obj);
    /// Like bind(), replacing what is bound there already.
    void rebind(const CosNaming::Name &name, CORBA::Object_ptr obj, bool force = true);
    void rebindByString(const char *string_name, CORBA::Object_ptr obj, bool force = true);
    static void rebindRecursive(CosNaming::NamingContext_ptr context, const CosNaming::Name &name,
                                CORBA::Object_ptr obj);

    /// bind() and rebind() for naming contexts.
    void bindContext(const CosNaming::Name &name, CosNaming::NamingContext_ptr name_cxt,
                     bool force = true);
    void bindContext(const char *string_name, CosNaming::NamingContext_ptr name_cxt,
                     bool force = true);
    void bindContextRecursive(CosNaming::NamingContext_ptr context, const CosNaming::Name &name,
                              CosNaming::NamingContext_ptr name_cxt);
    void rebindContext(const CosNaming::Name &name, CosNaming::NamingContext_ptr name_cxt,
                       bool force = true);
    void rebindContext(const char *string_name, CosNaming::NamingContext_ptr name_cxt,
                       bool force = true);
    static void rebindContextRecursive(CosNaming::NamingContext_ptr context,
                                       const CosNaming::Name &name,
                                       CosNaming::NamingContext_ptr name_cxt);

    /// The object bound at `name` (the caller releases it).
    CORBA::Object_ptr resolve(const CosNaming::Name &name);
    CORBA::Object_ptr resolve(const char *string_name);
    /// Removes the binding at `name`.
    void unbind(const CosNaming::Name &name);
    void unbind(const char *string_name);

    /// A new, unbound context of this name service.
    CosNaming::NamingContext_ptr newContext();
    /// A new context bound at `name`; with `force`, missing intermediate contexts are created.
    CosNaming::NamingContext_ptr bindNewContext(const CosNaming::Name &name, bool force = true);
    CosNaming::NamingContext_ptr bindNewContext(const char *string_name, bool force = true);
    /// Destroys `context` (it must be empty).
    static void destroy(CosNaming::NamingContext_ptr context);
    /// Unbinds everything below `context`, destroying the sub-contexts on the way.
    void destroyRecursive(CosNaming::NamingContext_ptr context);
    /// destroyRecursive() on the root context.
    void clearAll();

    /// The first `how_many` bindings of `name_cxt` in `bl`, the rest through `bi`.
    static void list(CosNaming::NamingContext_ptr name_cxt, CORBA::ULong how_many,
                     CosNaming::BindingList_var &bl, CosNaming::BindingIterator_var &bi);
    /// All bindings of the context at `string_name`; none when it is no context.
    void list(const char *string_name, CosNaming::BindingList_var &bl);
    /// The object bindings of the context at `string_name` whose last kind is `string_kind`.
    void listByKind(const char *string_name, const char *string_kind,
                    CosNaming::BindingList_var &bl);

    /// `name` as a string ("a.kind/b"), '/', '.' and '\' escaped with '\'.
    /// @throws InvalidName for an empty name.
    static char *toString(const CosNaming::Name &name);
    /// The inverse of toString(). @throws InvalidName for a null or empty string.
    static CosNaming::Name toName(const char *sname);
    /// A corbaname URL for `string_name` at address `addr` (the name service composes it).
    char *toUrl(char *addr, char *string_name);
    /// resolve() by string name.
    CORBA::Object_ptr resolveStr(const char *string_name);

    /// Binds `obj` at `name` in `context`, or returns what is bound there already.
    static CORBA::Object_ptr bindOrResolve(CosNaming::NamingContext_ptr context,
                                           const CosNaming::Name &name, CORBA::Object_ptr obj);
    static CosNaming::NamingContext_ptr bindOrResolveContext(CosNaming::NamingContext_ptr context,
                                                             const CosNaming::Name &name,
                                                             CosNaming::NamingContext_ptr new_context);
    CosNaming::NamingContext_ptr bindOrResolveContext(CosNaming::NamingContext_ptr context,
                                                      const CosNaming::Name &name);

    /// The URL the root context was resolved from.
    const char *getNameServer();
    /// The root context (the caller releases it).
    CosNaming::NamingContext_ptr getRootContext();
    /// Whether `obj` is a naming context.
    static bool isNamingContext(CORBA::Object_ptr obj);
    bool isNamingContext(const CosNaming::Name &name);
    bool isNamingContext(const char *string_name);
    /// Components `begin` to `end` (inclusive; -1: the last) of `name`.
    static CosNaming::Name subName(const CosNaming::Name &name, CORBA::Long begin,
                                   CORBA::Long end = -1);

protected:
    /// Writes toString() of `name` into `string_name`, which holds `slen` characters.
    static void nameToString(const CosNaming::Name &name, char *string_name, CORBA::ULong slen);
    /// The length of toString() of `name` plus one.
    static CORBA::ULong getNameLength(const CosNaming::Name &name);
    /// Splits `input` at each `delimiter` not preceded by '\'; empty parts are dropped.
    static unsigned int split(const std::string &input, const std::string &delimiter,
                              std::vector<std::string> &results);

    CORBA::ORB_ptr m_ptrORB;
    std::string m_nameServer;
    CosNaming::NamingContextExt_var m_rootContext;

private:
    CORBA::ULong m_blLength;
};
} // namespace RTC

#endif // RTC_CORBANAMING_H
