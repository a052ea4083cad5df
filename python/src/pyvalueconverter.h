// SPDX-License-Identifier: MIT
#pragma once

#include "idlmodel.h"

#include <pybind11/pybind11.h>

#include <QJsonValue>

namespace RtPython {

/**
 * Python values to and from the JSON values of Codegen::CdrCodec, by IDL type, in omniORBpy's
 * mapping: a struct is an object of its class with one attribute per member, an enum value one of
 * its class's items (`RTC.RTC_OK`), integers are int, floating types float, `char` and strings str,
 * `sequence<octet>` bytes, other sequences and arrays lists, a union an object of its class with
 * the discriminator in `_d` and the value in `_v`, an object reference None when nil and else a
 * `_rtstudio_interfaces.ObjectReference` holding its IOR, an `any` a `CORBA.Any` and a TypeCode
 * a `CORBA.TypeCode` naming its IDL type.
 */
class PyValueConverter
{
public:
    /// @p classes maps each struct's and enum's scoped name (`RTC::TimedLong`) to its Python class.
    PyValueConverter(const Codegen::IdlModel &model, pybind11::dict classes);

    /// @p value as the codec's value of @p type; throws pybind11::type_error naming the member.
    QJsonValue toJson(const Codegen::IdlType &type, pybind11::handle value, const QString &path) const;
    /// The Python value of the codec's @p value of @p type.
    pybind11::object toPython(const Codegen::IdlType &type, const QJsonValue &value) const;
    /// The model's type @p name names; refused (TypeError naming @p path) when it names none.
    Codegen::IdlType typeNamed(const QString &name, const QString &path) const;

    /**
     * While one lives in a thread, the references toPython() makes there are ones to call (a service
     * call's arguments and results), also of interfaces without a generated stub module (OpenRTM's
     * own RTC::PortService, …), whose operations are then called by name. Elsewhere (data samples)
     * such a reference is kept as its IOR.
     */
    class CallableReferences
    {
    public:
        CallableReferences();
        ~CallableReferences();
        CallableReferences(const CallableReferences &) = delete;
        CallableReferences &operator=(const CallableReferences &) = delete;

    private:
        bool m_before;
    };

private:
    QJsonValue basicToJson(const QString &keyword, pybind11::handle value, const QString &path) const;
    QJsonValue listToJson(const Codegen::IdlType &element, pybind11::handle value, const QString &path) const;
    QJsonValue namedToJson(const QString &name, pybind11::handle value, const QString &path) const;
    QJsonValue unionToJson(const Codegen::IdlUnion &type, pybind11::handle value, const QString &path) const;
    QJsonValue referenceToJson(pybind11::handle value, const QString &path) const;
    /// A received reference: one to call when @p interfaceName's stub module is imported, else
    /// kept as its IOR (an _rtstudio_interfaces.ObjectReference).
    pybind11::object referenceToPython(const QJsonValue &value, const QString &interfaceName = {}) const;
    static pybind11::object referenceClass();
    /// An `any` as omniORBpy's CORBA.Any (a CORBA.TypeCode and a value of its type) and back.
    QJsonValue anyToJson(pybind11::handle value, const QString &path) const;
    pybind11::object anyToPython(const QJsonValue &value) const;
    /// A CORBA.TypeCode as the name of its IDL type (Codegen::CdrTypeCode's text) and back.
    QJsonValue typeCodeToJson(pybind11::handle value, const QString &path) const;
    static pybind11::object typeCodeToPython(const QString &name);
    QJsonValue enumToJson(const Codegen::IdlEnum &type, pybind11::handle value, const QString &path) const;
    pybind11::object basicToPython(const QString &keyword, const QJsonValue &value) const;
    pybind11::object listToPython(const Codegen::IdlType &element, const QJsonValue &value) const;
    pybind11::object namedToPython(const QString &name, const QJsonValue &value) const;
    pybind11::object classOf(const QString &name) const;
    [[noreturn]] static void refuse(const QString &path, const QString &reason);

    const Codegen::IdlModel &m_model;
    pybind11::dict m_classes;
};

} // namespace RtPython
