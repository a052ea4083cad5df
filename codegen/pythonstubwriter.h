// SPDX-License-Identifier: MIT
#pragma once

#include "idlmodel.h"

#include <QMap>
#include <QString>
#include <QStringList>

namespace Codegen {

/**
 * The Python back end of our IDL compiler (`rtctl idl --lang python`): Python modules in
 * omniORBpy's layout and names for the declarations of some IDL files, run by RT Studio's Python
 * runtime instead of omniORBpy.
 *
 * For `MyService.idl` declaring module `SimpleService` it writes `MyService_idl.py` (the types:
 * constants, enums, structs, unions, typedefs, exceptions, `_objref_<I>` client classes and the
 * `SimpleService__POA.<I>` servant bases), and the packages `SimpleService/__init__.py` and
 * `SimpleService__POA/__init__.py` that import it; global declarations go to `_GlobalIDL`. Type ids
 * are omniORBpy's (`IDL:SimpleService/MyService:1.0`, `IDL:acme.com/Mod/I:1.0` after
 * `#pragma prefix "acme.com"`). The stub file carries the IDL text, which the runtime reads to
 * marshal calls and values by their IDL types; declarations of included files are taken from the
 * modules that already exist (OpenRTM's BasicDataType.idl, … from RTC), and those of included files
 * of the IDL file's own folder from their stub modules, which it imports (as omniidl's do).
 *
 * \code
 * IdlParser parser;
 * parser.parseFile(path);
 * const QMap<QString, QString> files = PythonStubWriter(parser.model()).write({path}, {text});
 * \endcode
 */
class PythonStubWriter
{
public:
    explicit PythonStubWriter(const IdlModel &model);

    /**
     * The files for the IDL files @p paths (as the parser opened them), whose texts are @p texts:
     * relative path in the output folder → content.
     */
    QMap<QString, QString> write(const QStringList &paths, const QStringList &texts) const;

    /// `IDL:Mod/Name:1.0` for the scoped name `Mod::Name` (with its file's `#pragma prefix`, if any).
    QString repositoryId(const QString &scopedName) const;

private:
    QString stubFile(const QString &path, const QString &text, QStringList *modules) const;
    /// declarationClasses() and, for a type, its TypeCode `Mod._tc_Name`.
    QString declaration(const IdlDeclaration &declaration, QStringList *classes) const;
    QString declarationClasses(const IdlDeclaration &declaration, QStringList *classes) const;
    QString structClass(const QString &scopedName, const QList<IdlMember> &members,
                        const QString &base) const;
    QString unionClass(const IdlUnion &type) const;
    QString enumItems(const IdlEnum &type) const;
    QString typedefClass(const QString &scopedName) const;
    QString interfaceClasses(const IdlInterface &type) const;
    QString constant(const IdlConst &constant) const;
    /// The top-level package of a declaration: its outermost module, or `_GlobalIDL`.
    QString packageOf(const QString &scopedName) const;
    /// The variable of the servant module holding interface @p interfaceName's `__POA` class.
    QString poaScopeOf(const QString &interfaceName) const;
    /// The Python expression of a scope: a module's variable, or a class of an enclosing interface.
    QString scopeExpression(const QString &scope) const;
    QString literal(const QString &idlValue) const;

    const IdlModel &m_model;
};

} // namespace Codegen
