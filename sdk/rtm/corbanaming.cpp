// SPDX-License-Identifier: MIT
#include <rtm/CORBA_RTCUtil.h>
#include <rtm/CorbaNaming.h>

#include <new>

namespace RTC {

namespace {

bool needsEscape(char c)
{
    return c == '/' || c == '.' || c == '\\';
}

// The characters toString() writes for one component, its trailing '/' included.
std::string componentText(const CosNaming::NameComponent &component)
{
    std::string text;
    auto escaped = [&text](const char *part) {
        for (; *part; ++part) {
            if (needsEscape(*part))
                text += '\\';
            text += *part;
        }
    };
    const char *id = component.id;
    const char *kind = component.kind;
    escaped(id);
    // "a" has no kind; ".b" and "a.b" need the dot, and so does the empty id (".").
    if (*id == '\0' || *kind != '\0')
        text += '.';
    escaped(kind);
    text += '/';
    return text;
}

// Splits one component at its last unescaped '.' and removes the escapes.
CosNaming::NameComponent parseComponent(const std::string &text)
{
    std::string id, kind;
    bool inKind = false;
    std::string::size_type lastDot = std::string::npos;
    for (std::string::size_type i = 0; i < text.size(); ++i) {
        if (text[i] == '\\')
            ++i;
        else if (text[i] == '.')
            lastDot = i;
    }
    for (std::string::size_type i = 0; i < text.size(); ++i) {
        if (i == lastDot) {
            inKind = true;
            continue;
        }
        if (text[i] == '\\' && i + 1 < text.size())
            ++i;
        (inKind ? kind : id) += text[i];
    }
    CosNaming::NameComponent component;
    component.id = CORBA::string_dup(id.c_str());
    component.kind = CORBA::string_dup(kind.c_str());
    return component;
}

// The context at the first `steps` components of `name` below `from`, each made (bind_new_context)
// where missing. A component bound to something else than a context ends the walk with
// CannotProceed, as a name service would report it.
CosNaming::NamingContext_ptr walkCreating(CosNaming::NamingContext_ptr from,
                                          const CosNaming::Name &name, CORBA::ULong steps)
{
    CosNaming::NamingContext_var current = CosNaming::NamingContext::_duplicate(from);
    for (CORBA::ULong i = 0; i < steps && i < name.length(); ++i) {
        CosNaming::Name step;
        step.length(1);
        step[0] = name[i];
        CosNaming::NamingContext_var next;
        try {
            next = current->bind_new_context(step);
        } catch (CosNaming::NamingContext::AlreadyBound &) {
            CORBA::Object_var bound = current->resolve(step);
            next = CosNaming::NamingContext::_narrow(bound);
        }
        if (CORBA::is_nil(next)) {
            CosNaming::Name rest;
            rest.length(name.length() - i);
            for (CORBA::ULong j = i; j < name.length(); ++j)
                rest[j - i] = name[j];
            throw CosNaming::NamingContext::CannotProceed(current, rest);
        }
        current = next._retn();
    }
    return current._retn();
}

CosNaming::Name lastOf(const CosNaming::Name &name)
{
    CosNaming::Name last;
    if (name.length() == 0)
        throw CosNaming::NamingContext::InvalidName();
    last.length(1);
    last[0] = name[name.length() - 1];
    return last;
}

} // namespace

CorbaNaming::CorbaNaming(CORBA::ORB_ptr orb)
    : m_ptrORB(orb)
    , m_rootContext(CosNaming::NamingContextExt::_nil())
    , m_blLength(100)
{ }

CorbaNaming::CorbaNaming(CORBA::ORB_ptr orb, const char *name_server)
    : CorbaNaming(orb)
{
    try {
        init(name_server);
    } catch (...) {
        // OpenRTM-aist reports every failure of this constructor the same way.
        throw std::bad_alloc();
    }
}

CorbaNaming::~CorbaNaming() = default;

void CorbaNaming::init(const char *name_server)
{
    m_nameServer
        = CORBA_RTCUtil::CorbaURI(name_server ? name_server : "", "NameService").toString();
    CORBA::Object_var object = m_ptrORB->string_to_object(m_nameServer.c_str());
    m_rootContext = CosNaming::NamingContextExt::_narrow(object);
    if (CORBA::is_nil(m_rootContext))
        throw std::bad_alloc();
}

bool CorbaNaming::isAlive()
{
    if (CORBA::is_nil(m_rootContext))
        return false;
    try {
        return !m_rootContext->_non_existent();
    } catch (...) {
        return false;
    }
}

void CorbaNaming::bind(const CosNaming::Name &name, CORBA::Object_ptr obj, bool force)
{
    try {
        m_rootContext->bind(name, obj);
    } catch (NotFound &) {
        if (!force)
            throw;
        bindRecursive(m_rootContext, name, obj);
    } catch (CannotProceed &e) {
        if (!force)
            throw;
        bindRecursive(e.cxt, e.rest_of_name, obj);
    }
}

void CorbaNaming::bindByString(const char *string_name, CORBA::Object_ptr obj, bool force)
{
    bind(toName(string_name), obj, force);
}

void CorbaNaming::bindRecursive(CosNaming::NamingContext_ptr context, const CosNaming::Name &name,
                                CORBA::Object_ptr obj)
{
    CosNaming::NamingContext_var parent = walkCreating(context, name, name.length() - 1);
    parent->bind(lastOf(name), obj);
}

void CorbaNaming::rebind(const CosNaming::Name &name, CORBA::Object_ptr obj, bool force)
{
    try {
        m_rootContext->rebind(name, obj);
    } catch (NotFound &) {
        if (!force)
            throw;
        rebindRecursive(m_rootContext, name, obj);
    } catch (CannotProceed &e) {
        if (!force)
            throw;
        rebindRecursive(e.cxt, e.rest_of_name, obj);
    }
}

void CorbaNaming::rebindByString(const char *string_name, CORBA::Object_ptr obj, bool force)
{
    rebind(toName(string_name), obj, force);
}

void CorbaNaming::rebindRecursive(CosNaming::NamingContext_ptr context, const CosNaming::Name &name,
                                  CORBA::Object_ptr obj)
{
    CosNaming::NamingContext_var parent = walkCreating(context, name, name.length() - 1);
    parent->rebind(lastOf(name), obj);
}

void CorbaNaming::bindContext(const CosNaming::Name &name, CosNaming::NamingContext_ptr name_cxt,
                              bool force)
{
    // bind_context, not bind: only context bindings take part in resolving compound names.
    try {
        m_rootContext->bind_context(name, name_cxt);
    } catch (NotFound &) {
        if (!force)
            throw;
        bindContextRecursive(m_rootContext, name, name_cxt);
    } catch (CannotProceed &) {
        if (!force)
            throw;
        bindContextRecursive(m_rootContext, name, name_cxt);
    }
}

void CorbaNaming::bindContext(const char *string_name, CosNaming::NamingContext_ptr name_cxt,
                              bool force)
{
    bindContext(toName(string_name), name_cxt, force);
}

void CorbaNaming::bindContextRecursive(CosNaming::NamingContext_ptr context,
                                       const CosNaming::Name &name,
                                       CosNaming::NamingContext_ptr name_cxt)
{
    CosNaming::NamingContext_var parent = walkCreating(context, name, name.length() - 1);
    parent->bind_context(lastOf(name), name_cxt);
}

void CorbaNaming::rebindContext(const CosNaming::Name &name, CosNaming::NamingContext_ptr name_cxt,
                                bool force)
{
    try {
        m_rootContext->rebind_context(name, name_cxt);
    } catch (NotFound &) {
        if (!force)
            throw;
        rebindContextRecursive(m_rootContext, name, name_cxt);
    } catch (CannotProceed &) {
        if (!force)
            throw;
        rebindContextRecursive(m_rootContext, name, name_cxt);
    }
}

void CorbaNaming::rebindContext(const char *string_name, CosNaming::NamingContext_ptr name_cxt,
                                bool force)
{
    rebindContext(toName(string_name), name_cxt, force);
}

void CorbaNaming::rebindContextRecursive(CosNaming::NamingContext_ptr context,
                                         const CosNaming::Name &name,
                                         CosNaming::NamingContext_ptr name_cxt)
{
    CosNaming::NamingContext_var parent = walkCreating(context, name, name.length() - 1);
    parent->rebind_context(lastOf(name), name_cxt);
}

CORBA::Object_ptr CorbaNaming::resolve(const CosNaming::Name &name)
{
    return m_rootContext->resolve(name);
}

CORBA::Object_ptr CorbaNaming::resolve(const char *string_name)
{
    return resolve(toName(string_name));
}

void CorbaNaming::unbind(const CosNaming::Name &name)
{
    m_rootContext->unbind(name);
}

void CorbaNaming::unbind(const char *string_name)
{
    unbind(toName(string_name));
}

CosNaming::NamingContext_ptr CorbaNaming::newContext()
{
    return m_rootContext->new_context();
}

CosNaming::NamingContext_ptr CorbaNaming::bindNewContext(const CosNaming::Name &name, bool force)
{
    try {
        return m_rootContext->bind_new_context(name);
    } catch (NotFound &) {
        if (!force)
            throw;
    } catch (CannotProceed &) {
        if (!force)
            throw;
    }
    // Makes the path's missing contexts, the last one included, and hands that one out.
    return walkCreating(m_rootContext, name, name.length());
}

CosNaming::NamingContext_ptr CorbaNaming::bindNewContext(const char *string_name, bool force)
{
    return bindNewContext(toName(string_name), force);
}

void CorbaNaming::destroy(CosNaming::NamingContext_ptr context)
{
    context->destroy();
}

void CorbaNaming::destroyRecursive(CosNaming::NamingContext_ptr context)
{
    CosNaming::BindingList_var bindings;
    CosNaming::BindingIterator_var more;
    context->list(m_blLength, bindings.out(), more.out());
    for (;;) {
        for (CORBA::ULong i = 0; i < bindings->length(); ++i) {
            const CosNaming::Binding &binding = bindings[i];
            if (binding.binding_type == CosNaming::ncontext) {
                CORBA::Object_var bound = context->resolve(binding.binding_name);
                CosNaming::NamingContext_var child = CosNaming::NamingContext::_narrow(bound);
                if (!CORBA::is_nil(child))
                    destroyRecursive(child);
                context->unbind(binding.binding_name);
                if (!CORBA::is_nil(child))
                    child->destroy();
            } else {
                context->unbind(binding.binding_name);
            }
        }
        if (CORBA::is_nil(more) || !more->next_n(m_blLength, bindings.out()))
            break;
    }
    if (!CORBA::is_nil(more))
        more->destroy();
}

void CorbaNaming::clearAll()
{
    destroyRecursive(m_rootContext);
}

void CorbaNaming::list(CosNaming::NamingContext_ptr name_cxt, CORBA::ULong how_many,
                       CosNaming::BindingList_var &bl, CosNaming::BindingIterator_var &bi)
{
    name_cxt->list(how_many, bl.out(), bi.out());
}

void CorbaNaming::list(const char *string_name, CosNaming::BindingList_var &bl)
{
    if (!bl.operator->())
        bl = new CosNaming::BindingList;
    bl->length(0);
    if (!string_name)
        return;
    CORBA::Object_var object = resolveStr(string_name);
    CosNaming::NamingContext_var context = CosNaming::NamingContext::_narrow(object);
    if (CORBA::is_nil(context))
        return;
    CosNaming::BindingIterator_var more;
    context->list(m_blLength, bl.out(), more.out());
    if (CORBA::is_nil(more))
        return;
    CosNaming::BindingList_var chunk;
    while (more->next_n(m_blLength, chunk.out())) {
        const CORBA::ULong start = bl->length();
        bl->length(start + chunk->length());
        for (CORBA::ULong i = 0; i < chunk->length(); ++i)
            bl[start + i] = chunk[i];
    }
    more->destroy();
}

void CorbaNaming::listByKind(const char *string_name, const char *string_kind,
                             CosNaming::BindingList_var &bl)
{
    if (!bl.operator->())
        bl = new CosNaming::BindingList;
    bl->length(0);
    if (!string_name || !string_kind)
        return;
    CosNaming::BindingList_var all;
    list(string_name, all);
    const std::string kind = string_kind;
    for (CORBA::ULong i = 0; i < all->length(); ++i) {
        const CosNaming::Binding &binding = all[i];
        const CORBA::ULong parts = binding.binding_name.length();
        if (binding.binding_type != CosNaming::nobject || parts == 0)
            continue;
        if (kind != static_cast<const char *>(binding.binding_name[parts - 1].kind))
            continue;
        bl->length(bl->length() + 1);
        bl[bl->length() - 1] = binding;
    }
}

char *CorbaNaming::toString(const CosNaming::Name &name)
{
    if (name.length() == 0)
        throw InvalidName();
    const CORBA::ULong length = getNameLength(name);
    char *text = CORBA::string_alloc(length);
    nameToString(name, text, length);
    return text;
}

CosNaming::Name CorbaNaming::toName(const char *sname)
{
    if (!sname || *sname == '\0')
        throw InvalidName();
    std::vector<std::string> parts;
    if (split(sname, "/", parts) == 0)
        throw InvalidName();
    CosNaming::Name name;
    name.length(CORBA::ULong(parts.size()));
    for (CORBA::ULong i = 0; i < name.length(); ++i)
        name[i] = parseComponent(parts[i]);
    return name;
}

char *CorbaNaming::toUrl(char *addr, char *string_name)
{
    return m_rootContext->to_url(addr, string_name);
}

CORBA::Object_ptr CorbaNaming::resolveStr(const char *string_name)
{
    return resolve(string_name);
}

CORBA::Object_ptr CorbaNaming::bindOrResolve(CosNaming::NamingContext_ptr context,
                                             const CosNaming::Name &name, CORBA::Object_ptr obj)
{
    try {
        context->bind(name, obj);
        return CORBA::Object::_duplicate(obj);
    } catch (AlreadyBound &) {
        return context->resolve(name);
    }
}

CosNaming::NamingContext_ptr
CorbaNaming::bindOrResolveContext(CosNaming::NamingContext_ptr context, const CosNaming::Name &name,
                                  CosNaming::NamingContext_ptr new_context)
{
    try {
        context->bind_context(name, new_context);
        return CosNaming::NamingContext::_duplicate(new_context);
    } catch (AlreadyBound &) {
        CORBA::Object_var bound = context->resolve(name);
        return CosNaming::NamingContext::_narrow(bound);
    }
}

CosNaming::NamingContext_ptr CorbaNaming::bindOrResolveContext(CosNaming::NamingContext_ptr context,
                                                               const CosNaming::Name &name)
{
    CosNaming::NamingContext_var fresh = newContext();
    CosNaming::NamingContext_ptr result = bindOrResolveContext(context, name, fresh);
    // A context that lost the race to an existing binding is of no use: remove it again.
    if (!fresh->_is_equivalent(result))
        fresh->destroy();
    return result;
}

const char *CorbaNaming::getNameServer()
{
    return m_nameServer.c_str();
}

CosNaming::NamingContext_ptr CorbaNaming::getRootContext()
{
    return CosNaming::NamingContext::_duplicate(m_rootContext);
}

bool CorbaNaming::isNamingContext(CORBA::Object_ptr obj)
{
    if (CORBA::is_nil(obj))
        return false;
    CosNaming::NamingContext_var context = CosNaming::NamingContext::_narrow(obj);
    return !CORBA::is_nil(context);
}

bool CorbaNaming::isNamingContext(const CosNaming::Name &name)
{
    CORBA::Object_var object = resolve(name);
    return isNamingContext(object.in());
}

bool CorbaNaming::isNamingContext(const char *string_name)
{
    CORBA::Object_var object = resolve(string_name);
    return isNamingContext(object.in());
}

CosNaming::Name CorbaNaming::subName(const CosNaming::Name &name, CORBA::Long begin,
                                     CORBA::Long end)
{
    if (end < 0)
        end = CORBA::Long(name.length()) - 1;
    CosNaming::Name part;
    if (begin < 0 || end < begin || end >= CORBA::Long(name.length()))
        return part;
    part.length(CORBA::ULong(end - begin + 1));
    for (CORBA::ULong i = 0; i < part.length(); ++i)
        part[i] = name[CORBA::ULong(begin) + i];
    return part;
}

void CorbaNaming::nameToString(const CosNaming::Name &name, char *string_name, CORBA::ULong slen)
{
    if (slen == 0)
        return;
    std::string text;
    for (CORBA::ULong i = 0; i < name.length(); ++i)
        text += componentText(name[i]);
    if (!text.empty())
        text.pop_back(); // no '/' after the last component
    const std::string::size_type kept = std::min<std::string::size_type>(text.size(), slen - 1);
    text.copy(string_name, kept);
    string_name[kept] = '\0';
}

CORBA::ULong CorbaNaming::getNameLength(const CosNaming::Name &name)
{
    // Each component's text ends in '/': the last one's becomes the terminating NUL.
    CORBA::ULong length = 0;
    for (CORBA::ULong i = 0; i < name.length(); ++i)
        length += CORBA::ULong(componentText(name[i]).size());
    return length;
}

unsigned int CorbaNaming::split(const std::string &input, const std::string &delimiter,
                                std::vector<std::string> &results)
{
    if (delimiter.empty()) {
        results.push_back(input);
        return unsigned(results.size());
    }
    std::string part;
    for (std::string::size_type i = 0; i < input.size();) {
        if (input[i] == '\\' && i + 1 < input.size()) {
            // Escapes stay in the part: the component parser needs them.
            part += input.substr(i, 2);
            i += 2;
        } else if (input.compare(i, delimiter.size(), delimiter) == 0) {
            if (!part.empty())
                results.push_back(part);
            part.clear();
            i += delimiter.size();
        } else {
            part += input[i++];
        }
    }
    if (!part.empty())
        results.push_back(part);
    return unsigned(results.size());
}

} // namespace RTC
