// SPDX-License-Identifier: MIT
#pragma once

#include <omniORB4/CORBA.h>

#include <pybind11/pybind11.h>

#include <string>

namespace RtPython {

/**
 * A servant written in Python (a subclass of a `<Module>__POA.<I>` class) behind a dynamic
 * skeleton: each request's arguments are read by the operation's IDL signature with the CDR codec,
 * the Python method is called with the GIL, and its result and out/inout values are written back.
 * An exception the operation declares (`raises`) goes back to the caller as that user exception;
 * any other Python exception is printed with its traceback and answered with CORBA::UNKNOWN.
 *
 * Reference counted as every ServantBase: the creator holds the first reference.
 */
class PyServant : public virtual PortableServer::ServantBase
{
public:
    /// @p servant's class names its interface in `_NP_RepositoryId`. Needs the GIL.
    explicit PyServant(pybind11::object servant);
    ~PyServant() override;

    /// The Python servant object (use with the GIL).
    pybind11::object servant() const { return m_servant; }
    /// The type id of its interface.
    const std::string &repositoryId() const { return m_repositoryId; }

    /// Answers an operation of the interface (or its bases); false leaves the others to omniServant.

    CORBA::Boolean _dispatch(omniCallHandle &handle) override;
    void *_ptrToInterface(const char *repositoryId) override;
    const char *_mostDerivedRepoId() override;
    CORBA::Boolean _is_a(const char *repositoryId) override;

private:
    pybind11::object m_servant;
    std::string m_repositoryId;
};

} // namespace RtPython
