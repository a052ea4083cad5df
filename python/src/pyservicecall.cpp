// SPDX-License-Identifier: MIT
#include "pyservicecall.h"
#include "pydatatypes.h"

#include "cdrcodec.h"

#include <omniORB4/IOP_C.h>

#include <QSysInfo>

#include <map>
#include <mutex>
#include <set>

namespace py = pybind11;
using Codegen::IdlOperation;
using Codegen::IdlParameter;
using Codegen::IdlType;

namespace RtPython {

namespace {

constexpr bool HostLittle = QSysInfo::ByteOrder == QSysInfo::LittleEndian;

/// An ORB's request or reply being read: omniORB aligns and throws MARSHAL when the message ends.
class StreamInput : public Codegen::CdrInput
{
public:
    explicit StreamInput(cdrStream &stream)
        : m_stream(stream)
    { }

    bool read(uchar *to, int size, int alignment) override
    {
        m_stream.get_octet_array(to, size, omni::alignment_t(alignment));
        return true;
    }
    bool available(quint64 bytes) const override
    {
        return bytes <= 0xffffffffu && m_stream.checkInputOverrun(1, CORBA::ULong(bytes));
    }

private:
    cdrStream &m_stream;
};

class StreamOutput : public Codegen::CdrOutput
{
public:
    explicit StreamOutput(cdrStream &stream)
        : m_stream(stream)
    { }

    void write(const uchar *from, int size, int alignment) override
    {
        m_stream.put_octet_array(from, size, omni::alignment_t(alignment));
    }

private:
    cdrStream &m_stream;
};

bool sendsValue(const IdlParameter &parameter)
{
    return parameter.mode != IdlParameter::Mode::Out;
}

bool returnsValue(const IdlParameter &parameter)
{
    return parameter.mode != IdlParameter::Mode::In;
}

/// A call made on a reference: the in/inout values go out, the result and out/inout values come
/// back.
class ClientCall : public omniCallDescriptor
{
public:
    ClientCall(const IdlOperation &operation, const QByteArray &name,
               const ExceptionIds &exceptions, std::vector<QJsonValue> inputs)
        // No local call function: omniORB then marshals a call to a servant of this process
        // through memory, so that C++ servants here are called as from another process.
        : omniCallDescriptor(nullptr, name.constData(), size_t(name.size()) + 1, operation.oneway,
                             exceptions.ids(), exceptions.count(), false)
        , m_operation(operation)
        , m_inputs(std::move(inputs))
    { }

    void marshalArguments(cdrStream &stream) override
    {
        size_t next = 0;
        for (const IdlParameter &parameter : m_operation.parameters) {
            if (sendsValue(parameter))
                writeValue(stream, parameter.type, m_inputs.at(next++));
        }
    }

    void unmarshalReturnedValues(cdrStream &stream) override
    {
        if (!m_operation.returnType.isVoid())
            m_outputs.push_back(readValue(stream, m_operation.returnType));
        for (const IdlParameter &parameter : m_operation.parameters) {
            if (returnsValue(parameter))
                m_outputs.push_back(readValue(stream, parameter.type));
        }
    }

    void userException(cdrStream &stream, omni::IOP_C *client, const char *repositoryId) override
    {
        const QString scopedName = PyDataTypes::instance().scopedNameOf(repositoryId);
        if (!m_operation.raises.contains(scopedName)) {
            if (client)
                client->RequestCompleted(1);
            OMNIORB_THROW(UNKNOWN, omni::UNKNOWN_UserException,
                          CORBA::CompletionStatus(stream.completion()));
        }
        DynamicUserException exception(scopedName, readValue(stream, IdlType::named(scopedName)));
        if (client)
            client->RequestCompleted();
        throw exception;
    }

    const std::vector<QJsonValue> &outputs() const { return m_outputs; }

private:
    const IdlOperation &m_operation;
    std::vector<QJsonValue> m_inputs;
    std::vector<QJsonValue> m_outputs;
};

/// The Python arguments of the in and inout parameters as the codec's values.
std::vector<QJsonValue> inputValues(const IdlOperation &operation, const py::tuple &arguments)
{
    const PyValueConverter &converter = PyDataTypes::instance().converter();
    std::vector<QJsonValue> inputs;
    for (const IdlParameter &parameter : operation.parameters) {
        if (sendsValue(parameter))
            inputs.push_back(
                converter.toJson(parameter.type, arguments[inputs.size()], parameter.name));
    }
    return inputs;
}

/// The results as omniORBpy returns them: None, the one value, or a tuple.
py::object resultObject(const IdlOperation &operation, const std::vector<QJsonValue> &outputs)
{
    const PyValueConverter &converter = PyDataTypes::instance().converter();
    std::vector<IdlType> types;
    if (!operation.returnType.isVoid())
        types.push_back(operation.returnType);
    for (const IdlParameter &parameter : operation.parameters) {
        if (returnsValue(parameter))
            types.push_back(parameter.type);
    }
    if (types.empty() || outputs.size() != types.size())
        return py::none();
    const PyValueConverter::CallableReferences callable;
    if (types.size() == 1)
        return converter.toPython(types.front(), outputs.front());
    py::tuple values(types.size());
    for (size_t i = 0; i < types.size(); ++i)
        values[i] = converter.toPython(types[i], outputs[i]);
    return std::move(values);
}

size_t inputCount(const IdlOperation &operation)
{
    return size_t(
        std::count_if(operation.parameters.cbegin(), operation.parameters.cend(), sendsValue));
}

} // namespace

std::optional<IdlOperation> findOperation(const Codegen::IdlModel &model,
                                          const std::string &repositoryId,
                                          const std::string &operation)
{
    const QString interface = PyDataTypes::instance().scopedNameOf(repositoryId);
    const QString name = QString::fromStdString(operation);
    for (const IdlOperation &candidate : model.allOperations(interface)) {
        if (candidate.name == name)
            return candidate;
    }
    // Attributes are reached through the operations _get_<name> and _set_<name>.
    for (const Codegen::IdlAttribute &attribute : model.allAttributes(interface)) {
        IdlOperation accessor;
        accessor.interfaceName = attribute.interfaceName;
        accessor.returnType = IdlType::basic(QStringLiteral("void"));
        if (name == QStringLiteral("_get_") + attribute.name) {
            accessor.name = name;
            accessor.returnType = attribute.type;
            return accessor;
        }
        if (!attribute.readonly && name == QStringLiteral("_set_") + attribute.name) {
            accessor.name = name;
            IdlParameter value;
            value.type = attribute.type;
            value.name = attribute.name;
            accessor.parameters.append(value);
            return accessor;
        }
    }
    return std::nullopt;
}

ExceptionIds::ExceptionIds(const IdlOperation &operation)
{
    // Never freed: interfaces are few, and omniORB may read the ids after any call has ended.
    static std::mutex mutex;
    static std::map<QString, std::vector<const char *>> *lists
        = new std::map<QString, std::vector<const char *>>;
    static std::set<std::string> *ids = new std::set<std::string>;
    const QString key = operation.interfaceName + QStringLiteral("::") + operation.name;
    std::lock_guard lock(mutex);
    auto [list, added] = lists->try_emplace(key);
    if (added) {
        for (const QString &exception : operation.raises)
            list->second.push_back(ids->insert(PyDataTypes::instance().repositoryIdOf(exception)).first->c_str());
    }
    m_pointers = &list->second;
}

QJsonValue readValue(cdrStream &stream, const IdlType &type)
{
    StreamInput input(stream);
    QString error;
    const QJsonValue value = PyDataTypes::instance().codec().read(
        type, input, HostLittle != stream.unmarshal_byte_swap(), &error);
    if (!error.isEmpty())
        OMNIORB_THROW(MARSHAL, 0, CORBA::COMPLETED_NO);
    return value;
}

void writeValue(cdrStream &stream, const IdlType &type, const QJsonValue &value)
{
    StreamOutput output(stream);
    QString error;
    if (!PyDataTypes::instance().codec().write(type, value, output,
                                               HostLittle != stream.marshal_byte_swap(), &error))
        OMNIORB_THROW(BAD_PARAM, 0, CORBA::COMPLETED_NO);
}

DynamicUserException::DynamicUserException(const QString &scopedName, const QJsonValue &members)
    : m_scopedName(scopedName)
    , m_repositoryId(PyDataTypes::instance().repositoryIdOf(scopedName))
    , m_members(members)
{ }

const char *DynamicUserException::_NP_typeId() const
{
    return "Exception/UserException/RtPython::DynamicUserException";
}

const char *DynamicUserException::_NP_repoId(int *size) const
{
    *size = int(m_repositoryId.size()) + 1;
    return m_repositoryId.c_str();
}

void DynamicUserException::_NP_marshal(cdrStream &stream) const
{
    writeValue(stream, IdlType::named(m_scopedName), m_members);
}

void raiseSystemException(const CORBA::SystemException &error)
{
    py::object cls = py::module_::import("omniORB.CORBA").attr(error._name());
    py::object instance = cls(py::int_(error.minor()), py::int_(int(error.completed())));
    PyErr_SetObject(cls.ptr(), instance.ptr());
    throw py::error_already_set();
}

py::object invokeOperation(CORBA::Object_ptr target, const std::string &repositoryId,
                           const std::string &operation, const py::tuple &arguments)
{
    const std::optional<IdlOperation> signature
        = findOperation(PyDataTypes::instance().model(), repositoryId, operation);
    if (!signature)
        throw py::attribute_error(repositoryId + " has no operation " + operation);
    if (size_t(arguments.size()) != inputCount(*signature))
        throw py::type_error(operation + "() takes " + std::to_string(inputCount(*signature))
                             + " arguments (" + std::to_string(arguments.size()) + " given)");
    const QByteArray name = QByteArray::fromStdString(operation);
    const ExceptionIds exceptions(*signature);
    ClientCall call(*signature, name, exceptions, inputValues(*signature, arguments));
    try {
        if (CORBA::is_nil(target))
            OMNIORB_THROW(INV_OBJREF, 0, CORBA::COMPLETED_NO);
        py::gil_scoped_release release;
        target->_PR_getobj()->_invoke(call);
    } catch (const DynamicUserException &exception) {
        py::object value = PyDataTypes::instance().converter().toPython(
            IdlType::named(exception.scopedName()), exception.members());
        PyErr_SetObject(reinterpret_cast<PyObject *>(Py_TYPE(value.ptr())), value.ptr());
        throw py::error_already_set();
    } catch (const CORBA::SystemException &error) {
        raiseSystemException(error);
    }
    return resultObject(*signature, call.outputs());
}

} // namespace RtPython
