// SPDX-License-Identifier: MIT
#pragma once

#include "cdrcodec.h"
#include "idltypelibrary.h"
#include "pydirectcdr.h"
#include "pyvalueconverter.h"

#include <QTemporaryDir>

#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <vector>

namespace RtPython {

/**
 * The IDL data types Python components exchange: the model read from OpenRTM's IDL files, the
 * Python class of each struct and enum (made by _rtstudio_idl from describe()), and samples encoded
 * to CDR and decoded from it by Codegen::CdrCodec. One per process; use it with the GIL held.
 */
class PyDataTypes
{
public:
    static PyDataTypes &instance();

    /// Reads every IDL file in @p directories; throws RuntimeError naming the problems.
    void load(const std::vector<std::string> &directories);
    /**
     * The declared types for making classes: `structs` (scoped name → member names in
     * declaration order), `enums` (scoped name → enumerator names), `consts` (scoped name →
     * integer value, for those that are integers), `unions` (scoped name → (the enum of the
     * discriminator or "", the discriminator's type, [(member, [label values], is default)])), `typecodes`
     * (the scoped names of every named type, for their TypeCodes), `files` (each IDL file's base
     * name → the top-level modules it declares in, for omniidl's `<Base>_idl` modules).
     */
    pybind11::dict describe() const;
    /// The classes of the structs and enums, by scoped name.
    void setClasses(pybind11::dict classes);
    /**
     * Adds the declarations of IDL @p text (a stub module's, named @p fileName); throws RuntimeError
     * with the parser's messages. Its includes are the IDL texts added before (a stub module imports
     * those of its own folder's included files first, as omniidl's do), then OpenRTM's IDL.
     * Exceptions are kept as structs too, so that their members convert as a struct's.
     */
    void addIdl(const std::string &fileName, const std::string &text);
    /// Adds classes (scoped name → class) to those of setClasses().
    void addClasses(const pybind11::dict &classes);

    const Codegen::IdlModel &model() const;
    /// The scoped name of the type id @p repositoryId, with its `#pragma prefix` if any.
    QString scopedNameOf(const std::string &repositoryId) const;
    /// The type id of @p scopedName, with its `#pragma prefix` if any.
    std::string repositoryIdOf(const QString &scopedName) const;
    const Codegen::CdrCodec &codec() const;
    const PyValueConverter &converter() const;

    /// The repository id of @p value's class (its `_NP_RepositoryId`); TypeError when it has none.
    static std::string repositoryId(pybind11::handle value);
    /**
     * @p value as CDR of the type @p repositoryId names; TypeError naming a member that does not fit.
     * Straight from the Python objects where PyDirectCdr can (@p direct), else through the converter.
     */
    std::vector<unsigned char> encode(const std::string &repositoryId, pybind11::handle value,
                                      bool littleEndian, bool direct = true) const;
    /// A new Python value from CDR of the type @p repositoryId names; ValueError when it does not decode.
    pybind11::object decode(const std::string &repositoryId, const unsigned char *data, size_t size,
                            bool littleEndian, bool direct = true) const;

    /// A new value of the type @p repositoryId names with every member zero or empty (OpenRTM-aist-Python's instantiateDataType()).
    pybind11::object defaultValue(const std::string &repositoryId) const;

private:
    PyDataTypes() = default;
    void rebuild();
    static pybind11::dict describeUnions(const Codegen::IdlModel &model);
    static pybind11::dict describeFiles(const Codegen::IdlModel &model);

    /// Writes @p text as @p fileName into the folder where added IDL texts find each other.
    QString keepIdlText(const std::string &fileName, const std::string &text);

    std::unique_ptr<Codegen::IdlTypeLibrary> m_library;
    /// The texts addIdl() was given, as files (by their names) that later texts may include.
    std::unique_ptr<QTemporaryDir> m_addedIdl;
    /// The library's model with the stub modules' declarations added.
    Codegen::IdlModel m_model;
    pybind11::dict m_classes;
    std::unique_ptr<Codegen::CdrCodec> m_codec;
    std::unique_ptr<PyValueConverter> m_converter;
    /// The way straight between Python objects and CDR, taken first where it can be.
    std::unique_ptr<PyDirectCdr> m_direct;
};

} // namespace RtPython
