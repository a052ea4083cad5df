// SPDX-License-Identifier: MIT
#include "pydatatypes.h"
#include "bindings.h"

#include "idlparser.h"

#include <pybind11/stl.h>

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QSet>

namespace py = pybind11;

namespace RtPython {

PyDataTypes &PyDataTypes::instance()
{
    // Never destroyed: it holds Python objects, and static destructors run after the interpreter is gone.
    static PyDataTypes *types = new PyDataTypes;
    return *types;
}

void PyDataTypes::load(const std::vector<std::string> &directories)
{
    QStringList folders;
    for (const std::string &directory : directories)
        folders << QString::fromStdString(directory);
    auto library = std::make_unique<Codegen::IdlTypeLibrary>(folders);
    if (library->model().structs.isEmpty())
        throw std::runtime_error("no IDL data types found in " + folders.join(QStringLiteral(", ")).toStdString());
    m_converter.reset();
    m_model = library->model();
    m_codec = std::make_unique<Codegen::CdrCodec>(m_model);
    m_library = std::move(library);
}

namespace {

template <typename Map>
void insertAll(Map &into, const Map &from)
{
    for (auto it = from.constBegin(); it != from.constEnd(); ++it)
        into.insert(it.key(), it.value());
}

} // namespace

void PyDataTypes::addIdl(const std::string &fileName, const std::string &text)
{
    if (!m_library)
        throw std::runtime_error("no IDL loaded (import RTC first)");
    Codegen::IdlParser parser;
    parser.setSearchDirectories(QStringList{keepIdlText(fileName, text)} + m_library->directories());
    if (!parser.parseText(QString::fromStdString(text), QString::fromStdString(fileName))) {
        QStringList messages;
        for (const Profile::Diagnostic &diagnostic : parser.diagnostics())
            messages << diagnostic.toString();
        throw std::runtime_error(messages.join(QLatin1Char('\n')).toStdString());
    }
    const Codegen::IdlModel &added = parser.model();
    insertAll(m_model.structs, added.structs);
    insertAll(m_model.unions, added.unions);
    insertAll(m_model.enums, added.enums);
    insertAll(m_model.typedefs, added.typedefs);
    insertAll(m_model.consts, added.consts);
    insertAll(m_model.exceptions, added.exceptions);
    insertAll(m_model.interfaces, added.interfaces);
    insertAll(m_model.prefixes, added.prefixes);
    for (const Codegen::IdlDeclaration &declaration : added.declarations) {
        if (!m_model.find(declaration.scopedName))
            m_model.declarations.append(declaration);
    }
    for (const Codegen::IdlException &exception : added.exceptions)
        m_model.structs.insert(exception.scopedName, {exception.scopedName, exception.members, exception.source});
    rebuild();
}

QString PyDataTypes::keepIdlText(const std::string &fileName, const std::string &text)
{
    if (!m_addedIdl)
        m_addedIdl = std::make_unique<QTemporaryDir>();
    QFile file(m_addedIdl->filePath(QFileInfo(QString::fromStdString(fileName)).fileName()));
    if (!file.open(QIODevice::WriteOnly) || file.write(QByteArray::fromStdString(text)) != qint64(text.size()))
        throw std::runtime_error("cannot keep the IDL text of " + fileName + " in " + m_addedIdl->path().toStdString());
    return m_addedIdl->path();
}

QString PyDataTypes::scopedNameOf(const std::string &repositoryId) const
{
    const QString id = QString::fromStdString(repositoryId);
    const QString scopedName = m_model.scopedNameOf(id);
    return scopedName.isEmpty() ? Codegen::CdrCodec::typeName(id) : scopedName;
}

std::string PyDataTypes::repositoryIdOf(const QString &scopedName) const
{
    return m_model.repositoryId(scopedName).toStdString();
}

void PyDataTypes::addClasses(const py::dict &classes)
{
    for (auto item : classes)
        m_classes[item.first] = item.second;
    rebuild();
}

void PyDataTypes::rebuild()
{
    m_codec = std::make_unique<Codegen::CdrCodec>(m_model);
    m_converter = std::make_unique<PyValueConverter>(m_model, m_classes);
    m_direct = std::make_unique<PyDirectCdr>(m_model, m_classes);
}

const Codegen::IdlModel &PyDataTypes::model() const
{
    return m_model;
}

const Codegen::CdrCodec &PyDataTypes::codec() const
{
    if (!m_codec)
        throw std::runtime_error("the IDL types are not loaded (import RTC first)");
    return *m_codec;
}

py::dict PyDataTypes::describe() const
{
    if (!m_library)
        throw std::runtime_error("no IDL loaded");
    const Codegen::IdlModel &model = m_library->model();
    py::dict structs, enums, consts;
    for (const Codegen::IdlStruct &type : model.structs) {
        py::list members;
        for (const Codegen::IdlMember &member : type.members)
            members.append(member.name.toStdString());
        structs[py::str(type.scopedName.toStdString())] = members;
    }
    for (const Codegen::IdlEnum &type : model.enums) {
        py::list names;
        for (const QString &name : type.enumerators)
            names.append(name.toStdString());
        enums[py::str(type.scopedName.toStdString())] = names;
    }
    for (const Codegen::IdlConst &constant : model.consts) {
        if (const std::optional<qint64> value = constant.integerValue())
            consts[py::str(constant.scopedName.toStdString())] = py::int_(static_cast<long long>(*value));
    }
    // Every named type, for its `_tc_<Name>` TypeCode in its module.
    py::list named;
    const auto addNames = [&named](const auto &types) {
        for (auto it = types.keyBegin(); it != types.keyEnd(); ++it)
            named.append(it->toStdString());
    };
    addNames(model.structs);
    addNames(model.unions);
    addNames(model.enums);
    addNames(model.typedefs);
    addNames(model.exceptions);
    addNames(model.interfaces);
    py::dict description;
    description["files"] = describeFiles(model);
    description["typecodes"] = named;
    description["unions"] = describeUnions(model);
    description["structs"] = structs;
    description["enums"] = enums;
    description["consts"] = consts;
    return description;
}

namespace {

/// A case label as Python has it before the enum classes exist: an enumerator's name, bool or int.
py::object labelObject(const QJsonValue &label)
{
    if (label.isString())
        return py::str(label.toString().toStdString());
    if (label.isBool())
        return py::bool_(label.toBool());
    return py::int_(static_cast<long long>(label.toInteger()));
}

} // namespace

py::dict PyDataTypes::describeFiles(const Codegen::IdlModel &model)
{
    // Each file's base name → the top-level modules it declares things in (omniidl's <Base>_idl).
    QMap<QString, QSet<QString>> modules;
    for (const Codegen::IdlDeclaration &declaration : model.declarations) {
        if (declaration.kind == Codegen::IdlDeclaration::Kind::Module || declaration.source.file.isEmpty())
            continue;
        const QString top = declaration.scopedName.contains(QStringLiteral("::"))
            ? declaration.scopedName.section(QStringLiteral("::"), 0, 0) : QStringLiteral("_GlobalIDL");
        modules[QFileInfo(declaration.source.file).completeBaseName()].insert(top);
    }
    py::dict files;
    for (auto it = modules.constBegin(); it != modules.constEnd(); ++it) {
        QStringList names = it.value().values();
        names.sort();
        py::list list;
        for (const QString &name : std::as_const(names))
            list.append(name.toStdString());
        files[py::str(it.key().toStdString())] = list;
    }
    return files;
}

py::dict PyDataTypes::describeUnions(const Codegen::IdlModel &model)
{
    // Each union: the enum of its discriminator (empty for a number, boolean or character) and its
    // cases as (member, discriminator values of the labels, whether it is the default).
    py::dict unions;
    for (const Codegen::IdlUnion &type : model.unions) {
        const Codegen::IdlType discriminator = model.resolve(type.discriminator);
        py::list cases;
        for (const Codegen::IdlUnionCase &c : type.cases) {
            py::list labels;
            for (const QString &label : c.labels)
                labels.append(labelObject(Codegen::CdrCodec::labelValue(model, type, label)));
            cases.append(py::make_tuple(c.member.name.toStdString(), labels, c.isDefault));
        }
        const bool isEnum = discriminator.kind == Codegen::IdlType::Kind::Named;
        unions[py::str(type.scopedName.toStdString())] =
            py::make_tuple(isEnum ? discriminator.name.toStdString() : std::string(), discriminator.name.toStdString(), cases);
    }
    return unions;
}

void PyDataTypes::setClasses(py::dict classes)
{
    if (!m_library)
        throw std::runtime_error("no IDL loaded");
    m_classes = std::move(classes);
    rebuild();
}

const PyValueConverter &PyDataTypes::converter() const
{
    if (!m_converter)
        throw std::runtime_error("the IDL types are not loaded (import RTC first)");
    return *m_converter;
}

std::string PyDataTypes::repositoryId(py::handle value)
{
    if (!py::hasattr(value, "_NP_RepositoryId"))
        throw py::type_error("a value of an IDL data type (such as RTC.TimedLong) is needed");
    return value.attr("_NP_RepositoryId").cast<std::string>();
}

std::vector<unsigned char> PyDataTypes::encode(const std::string &repositoryId, py::handle value,
                                               bool littleEndian, bool direct) const
{
    const QString type = Codegen::CdrCodec::typeName(QString::fromStdString(repositoryId));
    std::vector<unsigned char> bytes;
    if (direct && m_direct && m_direct->handles(type) && m_direct->encode(type, value, littleEndian, &bytes))
        return bytes;
    // What the direct way does not take, and values that do not fit (the converter says why).
    const QJsonValue json = converter().toJson(Codegen::IdlType::named(type), value, type);
    QString error;
    const QByteArray encoded = m_codec->encode(type, json, littleEndian, &error);
    if (!error.isEmpty())
        throw py::type_error(error.toStdString());
    return {encoded.begin(), encoded.end()};
}

py::object PyDataTypes::decode(const std::string &repositoryId, const unsigned char *data, size_t size,
                               bool littleEndian, bool direct) const
{
    const QString type = Codegen::CdrCodec::typeName(QString::fromStdString(repositoryId));
    if (direct && m_direct && m_direct->handles(type)) {
        if (std::optional<py::object> value = m_direct->decode(type, data, size, littleEndian))
            return std::move(*value);
    }
    QString error;
    const QJsonValue json = m_codec->decode(
        type, QByteArray::fromRawData(reinterpret_cast<const char *>(data), qsizetype(size)), littleEndian, &error);
    if (!error.isEmpty())
        throw py::value_error(error.toStdString());
    return converter().toPython(Codegen::IdlType::named(type), json);
}

py::object PyDataTypes::defaultValue(const std::string &repositoryId) const
{
    if (!m_library)
        throw std::runtime_error("no IDL loaded");
    const Codegen::IdlModel &model = m_model;
    const QString type = Codegen::CdrCodec::typeName(QString::fromStdString(repositoryId));
    // The codec takes members left out as zero or empty, except a timed type's time stamp, which
    // it sets to now unless the value names it: an empty `tm` is a zero time.
    QJsonObject members;
    const auto declared = model.structs.constFind(type);
    if (declared != model.structs.constEnd() && model.isTimed(*declared))
        members.insert(QStringLiteral("tm"), QJsonObject());
    QString error;
    const QByteArray bytes = m_codec->encode(type, members, true, &error);
    if (!error.isEmpty())
        throw py::type_error("no default value for " + repositoryId + ": " + error.toStdString());
    return decode(repositoryId, reinterpret_cast<const unsigned char *>(bytes.constData()), size_t(bytes.size()), true);
}

void bindDataTypes(py::module_ &module)
{
    module.def("load_idl", [](const std::vector<std::string> &directories) {
        PyDataTypes::instance().load(directories);
        return PyDataTypes::instance().describe();
    }, py::arg("directories"), "Reads OpenRTM's IDL files; the types they declare, for making classes.");
    module.def("set_idl_classes", [](py::dict classes) { PyDataTypes::instance().setClasses(std::move(classes)); },
               py::arg("classes"), "The Python class of each struct and enum, by scoped name.");
    module.def("add_idl", [](const std::string &fileName, const std::string &text) {
        PyDataTypes::instance().addIdl(fileName, text);
    }, py::arg("file_name"), py::arg("text"), "Adds the declarations of a stub module's IDL.");
    module.def("add_idl_classes", [](const py::dict &classes) { PyDataTypes::instance().addClasses(classes); },
               py::arg("classes"), "More Python classes of IDL types, by scoped name.");
    module.def("cdr_encode", [](py::handle value, bool littleEndian, bool direct) {
        const std::vector<unsigned char> bytes =
            PyDataTypes::instance().encode(PyDataTypes::repositoryId(value), value, littleEndian, direct);
        return py::bytes(reinterpret_cast<const char *>(bytes.data()), bytes.size());
    }, py::arg("value"), py::arg("little_endian") = true, py::arg("direct") = true,
       "A value of an IDL data type as CDR bytes (direct=False: through the converter, to compare).");
    module.def("default_value", [](const std::string &repositoryId) {
        return PyDataTypes::instance().defaultValue(repositoryId);
    }, py::arg("repository_id"), "A new value of an IDL data type with every member zero or empty.");
    module.def("cdr_decode", [](const std::string &repositoryId, const py::bytes &data, bool littleEndian, bool direct) {
        const std::string bytes = data;
        return PyDataTypes::instance().decode(repositoryId, reinterpret_cast<const unsigned char *>(bytes.data()),
                                              bytes.size(), littleEndian, direct);
    }, py::arg("repository_id"), py::arg("data"), py::arg("little_endian") = true, py::arg("direct") = true,
       "A new value of the IDL data type @p repository_id from CDR bytes.");
}

} // namespace RtPython
