// SPDX-License-Identifier: MIT
#pragma once

#include "idlmodel.h"

#include <omniORB4/CORBA.h>
#include <omniORB4/callDescriptor.h>

#include <pybind11/pybind11.h>

#include <QJsonValue>

#include <optional>
#include <string>
#include <vector>

namespace RtPython {

/**
 * The IDL signature of an operation of an interface (or of an attribute's `_get_x` / `_set_x`),
 * found in the model the stub modules added to (PyDataTypes).
 */
std::optional<Codegen::IdlOperation> findOperation(const Codegen::IdlModel &model,
                                                   const std::string &repositoryId,
                                                   const std::string &operation);

/**
 * The repository ids of the user exceptions @p operation raises, as omniORB's call descriptors want
 * them. Kept for the life of the process: omniORB reads them after the call descriptor is gone,
 * while it marshals a user exception the servant raised.
 */
class ExceptionIds
{
public:
    explicit ExceptionIds(const Codegen::IdlOperation &operation);
    const char *const *ids() const { return m_pointers->data(); }
    int count() const { return int(m_pointers->size()); }

private:
    const std::vector<const char *> *m_pointers;
};

/// Reads one value of @p type from an ORB stream with the codec; CORBA::MARSHAL when it does not
/// decode.
QJsonValue readValue(cdrStream &stream, const Codegen::IdlType &type);
/// Writes one value of @p type to an ORB stream with the codec; CORBA::BAD_PARAM when it does not
/// fit.
void writeValue(cdrStream &stream, const Codegen::IdlType &type, const QJsonValue &value);

/**
 * A user exception declared in IDL, with its members as the codec's value: raised by a Python
 * servant (marshalled into the reply), or received by a call (turned into the Python class).
 */
class DynamicUserException : public CORBA::UserException
{
public:
    DynamicUserException(const QString &scopedName, const QJsonValue &members);

    QString scopedName() const { return m_scopedName; }
    QJsonValue members() const { return m_members; }

    void _raise() const override { throw *this; }
    CORBA::Exception *_NP_duplicate() const override { return new DynamicUserException(*this); }

private:
    const char *_NP_typeId() const override;
    const char *_NP_repoId(int *size) const override;
    void _NP_marshal(cdrStream &stream) const override;

    QString m_scopedName;
    std::string m_repositoryId;
    QJsonValue m_members;
};

/**
 * Calls operation @p operation of the object @p target with Python arguments @p arguments (the
 * in and inout parameters in order), marshalled by its IDL signature, and returns as omniORBpy
 * does: the result, or a tuple of the result and the out/inout values, or None. Raises the
 * Python class of a user exception, or omniORB.CORBA's system exception. Takes the GIL; releases
 * it during the call.
 */
pybind11::object invokeOperation(CORBA::Object_ptr target, const std::string &repositoryId,
                                 const std::string &operation, const pybind11::tuple &arguments);

/// Raises @p error (a CORBA system exception) in Python as omniORB.CORBA's class of that name.
[[noreturn]] void raiseSystemException(const CORBA::SystemException &error);

} // namespace RtPython
