// SPDX-License-Identifier: MIT
// The ORB's own calls as omniORBpy's CORBA.ORB makes them (string_to_object, object_to_string,
// resolve_initial_references) and a servant's implicit activation (_this()), over the ORB and
// root POA of the process's manager; omniORB/CORBA.py and PortableServer.py wrap them.
#include "bindings.h"
#include "pydatatypes.h"
#include "pyiorform.h"
#include "pyobjectref.h"
#include "pyservant.h"
#include "pyservicecall.h"

#include <rtmruntime/corbautil.h>

namespace py = pybind11;

namespace RtPython {

namespace {

/// Runs @p call, which may reach a name server or another process, without the GIL; CORBA's system
/// exceptions become omniORB.CORBA's.
template <typename Call>
PyObjectRef withoutGil(Call &&call)
{
    CORBA::Object_var object;
    try {
        py::gil_scoped_release released;
        object = call(Runtime::theOrb());
    } catch (const CORBA::SystemException &error) {
        raiseSystemException(error);
    } catch (const CORBA::ORB::InvalidName &) {
        throw py::value_error("no such initial reference");
    }
    return PyObjectRef(object.in());
}

PyObjectRef stringToObject(const std::string &text)
{
    return withoutGil([&text](CORBA::ORB_ptr orb) { return orb->string_to_object(text.c_str()); });
}

PyObjectRef initialReference(const std::string &name)
{
    return withoutGil([&name](CORBA::ORB_ptr orb) { return orb->resolve_initial_references(name.c_str()); });
}

/// Activates the Python servant @p servant on the root POA (once: its reference is kept on it).
PyObjectRef activateServant(py::object servant)
{
    if (!py::hasattr(servant, "_NP_RepositoryId"))
        throw py::type_error("_this(): the servant must be of a generated <Module>__POA class");
    auto *bridge = new PyServant(servant);
    return withoutGil([bridge](CORBA::ORB_ptr orb) {
        CORBA::Object_var poaObject = orb->resolve_initial_references("RootPOA");
        PortableServer::POA_var poa = PortableServer::POA::_narrow(poaObject);
        PortableServer::ObjectId_var id = poa->activate_object(bridge);
        // The POA holds the bridge from here on.
        bridge->_remove_ref();
        return poa->id_to_reference(id.in());
    });
}

} // namespace

void bindOrb(py::module_ &module)
{
    module.def("string_to_object", &stringToObject, py::arg("text"));
    module.def("resolve_initial_references", &initialReference, py::arg("identifier"));
    module.def("activate_servant", &activateServant, py::arg("servant"));
    module.def("knows_interface", [](const std::string &repositoryId) {
        const PyDataTypes &types = PyDataTypes::instance();
        return types.model().interfaces.contains(types.scopedNameOf(repositoryId));
    }, py::arg("repository_id"));
    module.def("interface_ids", [](const std::string &moduleName) {
        // The interfaces declared directly in IDL module moduleName, by name, with their type ids.
        const PyDataTypes &types = PyDataTypes::instance();
        const QString prefix = QString::fromStdString(moduleName) + QStringLiteral("::");
        py::dict ids;
        for (const QString &name : types.model().interfaces.keys()) {
            if (name.startsWith(prefix) && !name.mid(prefix.size()).contains(QLatin1Char(':')))
                ids[py::str(name.mid(prefix.size()).toStdString())] = types.repositoryIdOf(name);
        }
        return ids;
    }, py::arg("module"));
    module.def("ior_type_id", [](const std::string &ior) {
        return IorForm::fromIor(ior)[QStringLiteral("type_id")].toString().toStdString();
    }, py::arg("ior"));
}

} // namespace RtPython
