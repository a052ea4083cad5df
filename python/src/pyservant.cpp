// SPDX-License-Identifier: MIT
#include "pyservant.h"
#include "pydatatypes.h"
#include "pyinterpreter.h"
#include "pyservicecall.h"

#include "cdrcodec.h"

#include <omniORB4/callHandle.h>

namespace py = pybind11;
using Codegen::IdlOperation;
using Codegen::IdlParameter;
using Codegen::IdlType;

namespace RtPython {

namespace {

/// One request to a Python servant: arguments in, the Python call, results out.
class ServerCall : public omniCallDescriptor
{
public:
    ServerCall(const IdlOperation &operation, const char *name, const ExceptionIds &exceptions)
        : omniCallDescriptor(&ServerCall::upcall, name, std::strlen(name) + 1, operation.oneway,
                             exceptions.ids(), exceptions.count(), true)
        , m_operation(operation)
    { }

    void unmarshalArguments(cdrStream &stream) override
    {
        for (const IdlParameter &parameter : m_operation.parameters) {
            if (parameter.mode != IdlParameter::Mode::Out)
                m_inputs.push_back(readValue(stream, parameter.type));
        }
    }

    void marshalReturnedValues(cdrStream &stream) override
    {
        const std::vector<IdlType> types = outputTypes();
        for (size_t i = 0; i < types.size() && i < m_outputs.size(); ++i)
            writeValue(stream, types[i], m_outputs[i]);
    }

private:
    static void upcall(omniCallDescriptor *descriptor, omniServant *servant)
    {
        auto *target = dynamic_cast<PyServant *>(servant);
        if (target == nullptr || !interpreterAlive())
            OMNIORB_THROW(OBJECT_NOT_EXIST, 0, CORBA::COMPLETED_NO);
        static_cast<ServerCall *>(descriptor)->callPython(*target);
    }

    std::vector<IdlType> outputTypes() const
    {
        std::vector<IdlType> types;
        if (!m_operation.returnType.isVoid())
            types.push_back(m_operation.returnType);
        for (const IdlParameter &parameter : m_operation.parameters) {
            if (parameter.mode != IdlParameter::Mode::In)
                types.push_back(parameter.type);
        }
        return types;
    }

    void callPython(PyServant &target)
    {
        Gil gil;
        const PyValueConverter &converter = PyDataTypes::instance().converter();
        try {
            const PyValueConverter::CallableReferences callable;
            py::tuple arguments(m_inputs.size());
            size_t next = 0;
            for (const IdlParameter &parameter : m_operation.parameters) {
                if (parameter.mode != IdlParameter::Mode::Out) {
                    arguments[next] = converter.toPython(parameter.type, m_inputs[next]);
                    ++next;
                }
            }
            const py::object result = target.servant().attr(op())(*arguments);
            keepResults(result);
        } catch (py::error_already_set &error) {
            raiseBack(error);
        }
    }

    /// The method's result as omniORBpy's servants return it: the one value, or a tuple of them.
    void keepResults(const py::object &result)
    {
        const PyValueConverter &converter = PyDataTypes::instance().converter();
        const std::vector<IdlType> types = outputTypes();
        if (types.size() == 1) {
            m_outputs.push_back(converter.toJson(types.front(), result, QString::fromLatin1(op())));
            return;
        }
        if (types.empty())
            return;
        const py::sequence values = result.cast<py::sequence>();
        if (size_t(values.size()) != types.size())
            throw py::type_error(std::string(op()) + "() must return "
                                 + std::to_string(types.size()) + " values");
        for (size_t i = 0; i < types.size(); ++i)
            m_outputs.push_back(converter.toJson(types[i], values[i], QString::fromLatin1(op())));
    }

    /// A declared user exception goes back to the caller; anything else is reported here.
    [[noreturn]] void raiseBack(py::error_already_set &error)
    {
        const py::object value = error.value();
        if (py::hasattr(value, "_NP_RepositoryId")) {
            const QString scopedName =
                PyDataTypes::instance().scopedNameOf(value.attr("_NP_RepositoryId").cast<std::string>());
            if (m_operation.raises.contains(scopedName)) {
                const QJsonValue members = PyDataTypes::instance().converter().toJson(
                    IdlType::named(scopedName), value, scopedName);
                throw DynamicUserException(scopedName, members);
            }
        }
        printError(std::string("the servant's ") + op() + "() raised an exception:", error);
        OMNIORB_THROW(UNKNOWN, 0, CORBA::COMPLETED_MAYBE);
    }

    const IdlOperation &m_operation;
    std::vector<QJsonValue> m_inputs;
    std::vector<QJsonValue> m_outputs;
};

} // namespace

PyServant::PyServant(py::object servant)
    : m_servant(std::move(servant))
    , m_repositoryId(m_servant.attr("_NP_RepositoryId").cast<std::string>())
{ }

PyServant::~PyServant()
{
    releasePython(m_servant);
}

CORBA::Boolean PyServant::_dispatch(omniCallHandle &handle)
{
    const std::optional<IdlOperation> operation
        = findOperation(PyDataTypes::instance().model(), m_repositoryId, handle.operation_name());
    if (!operation)
        return false; // _is_a, _non_existent, … are answered by omniServant
    const ExceptionIds exceptions(*operation);
    ServerCall call(*operation, handle.operation_name(), exceptions);
    handle.upcall(this, call);
    return true;
}

void *PyServant::_ptrToInterface(const char *repositoryId)
{
    // Only the untyped interface: typed stubs of this process must not call in directly.
    if (omni::ptrStrMatch(repositoryId, CORBA::Object::_PD_repoId))
        return static_cast<void *>(this);
    return nullptr;
}

const char *PyServant::_mostDerivedRepoId()
{
    return m_repositoryId.c_str();
}

CORBA::Boolean PyServant::_is_a(const char *repositoryId)
{
    if (m_repositoryId == repositoryId || std::string(repositoryId) == CORBA::Object::_PD_repoId)
        return true;
    const PyDataTypes &types = PyDataTypes::instance();
    for (const QString &base : types.model().allBases(types.scopedNameOf(m_repositoryId))) {
        if (types.repositoryIdOf(base) == repositoryId)
            return true;
    }
    return false;
}

} // namespace RtPython
