// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace Codegen {

/// Where an IDL declaration was written. Never part of equality.
struct IdlSource
{
    QString file; ///< path of the file as opened by the parser
    int line = 0; ///< 1-based
    int column = 0; ///< 1-based
};

/// An IDL type expression as written in a declaration, with names fully scoped.
struct IdlType
{
    enum class Kind {
        Basic,    ///< long, unsigned long, double, boolean, any, Object, void, ... (text in `name`)
        Named,    ///< a user-declared type; `name` is the scoped name, e.g. `RTC::Time`
        Sequence, ///< sequence<element[, bound]>
        String,   ///< string or string<bound>
        WString,  ///< wstring or wstring<bound>
        Fixed,    ///< fixed<digits, scale> (values in `bound` and `scale`), or plain `fixed`
        Array     ///< element[d1][d2]...; dimensions in `dimensions`
    };

    Kind kind = Kind::Basic;
    QString name;             ///< Basic: keyword text; Named: scoped name
    std::vector<IdlType> element; ///< Sequence/Array: exactly one element type
    QString bound;            ///< evaluated bound of sequence/string/wstring, digits of fixed; empty when unbounded
    QString scale;            ///< scale of fixed
    QStringList dimensions;   ///< Array: evaluated sizes, outermost first

    static IdlType basic(const QString &keyword);
    static IdlType named(const QString &scopedName);

    /// The type in IDL syntax with scoped names: `sequence<RTC::TimedLong, 4>`, `long[3][4]`.
    QString toString() const;
    bool isVoid() const { return kind == Kind::Basic && name == QLatin1String("void"); }

    bool operator==(const IdlType &other) const;
    bool operator!=(const IdlType &other) const { return !(*this == other); }
};

/// A field of a struct or exception, or the member of a union case.
struct IdlMember
{
    QString name;
    IdlType type; ///< arrays appear as Kind::Array
    IdlSource source;

    bool operator==(const IdlMember &other) const;
    bool operator!=(const IdlMember &other) const { return !(*this == other); }
};

struct IdlStruct
{
    QString scopedName;
    QList<IdlMember> members;
    IdlSource source;

    bool operator==(const IdlStruct &other) const;
    bool operator!=(const IdlStruct &other) const { return !(*this == other); }
};

/// One `case` group of a union: its labels (evaluated text) and its member.
struct IdlUnionCase
{
    QStringList labels;
    bool isDefault = false;
    IdlMember member;

    bool operator==(const IdlUnionCase &other) const;
    bool operator!=(const IdlUnionCase &other) const { return !(*this == other); }
};

struct IdlUnion
{
    QString scopedName;
    IdlType discriminator;
    QList<IdlUnionCase> cases;
    IdlSource source;

    bool operator==(const IdlUnion &other) const;
    bool operator!=(const IdlUnion &other) const { return !(*this == other); }
};

struct IdlEnum
{
    QString scopedName;
    QStringList enumerators; ///< plain names, in declaration order
    IdlSource source;

    bool operator==(const IdlEnum &other) const;
    bool operator!=(const IdlEnum &other) const { return !(*this == other); }
};

/// A typedef, or a value box (`valuetype Name type;`), which behaves like one for our purposes.
struct IdlTypedef
{
    QString scopedName;
    IdlType type;
    IdlSource source;

    bool operator==(const IdlTypedef &other) const;
    bool operator!=(const IdlTypedef &other) const { return !(*this == other); }
};

struct IdlConst
{
    QString scopedName;
    IdlType type;
    QString value; ///< evaluated value in IDL literal form: `42`, `2.5`, `"text"`, `'c'`, `TRUE`, `Mod::Enumerator`

    /// The value as an integer when it is one.
    std::optional<qint64> integerValue() const;

    IdlSource source;

    bool operator==(const IdlConst &other) const;
    bool operator!=(const IdlConst &other) const { return !(*this == other); }
};

struct IdlException
{
    QString scopedName;
    QList<IdlMember> members;
    IdlSource source;

    bool operator==(const IdlException &other) const;
    bool operator!=(const IdlException &other) const { return !(*this == other); }
};

struct IdlParameter
{
    enum class Mode { In, Out, InOut };

    Mode mode = Mode::In;
    IdlType type;
    QString name;
    IdlSource source;

    static QString modeName(Mode mode); ///< "in", "out", "inout"

    bool operator==(const IdlParameter &other) const;
    bool operator!=(const IdlParameter &other) const { return !(*this == other); }
};

struct IdlOperation
{
    QString name;
    QString interfaceName; ///< scoped name of the interface that declares it
    bool oneway = false;
    IdlType returnType;
    QList<IdlParameter> parameters;
    QStringList raises;   ///< scoped exception names
    QStringList contexts; ///< string literals of `context(...)`, without quotes
    IdlSource source;

    bool operator==(const IdlOperation &other) const;
    bool operator!=(const IdlOperation &other) const { return !(*this == other); }
};

struct IdlAttribute
{
    QString name;
    QString interfaceName;
    bool readonly = false;
    IdlType type;
    IdlSource source;

    bool operator==(const IdlAttribute &other) const;
    bool operator!=(const IdlAttribute &other) const { return !(*this == other); }
};

struct IdlInterface
{
    QString scopedName;
    bool defined = false; ///< false while only forward-declared
    bool isAbstract = false;
    bool isLocal = false;
    QStringList bases; ///< scoped names of the direct base interfaces
    QList<IdlOperation> operations; ///< own operations only, see IdlModel::allOperations()
    QList<IdlAttribute> attributes;
    IdlSource source; ///< of the definition, or of the first forward declaration

    bool operator==(const IdlInterface &other) const;
    bool operator!=(const IdlInterface &other) const { return !(*this == other); }
};

/// One node of the declaration tree: every named thing in declaration order.
struct IdlDeclaration
{
    enum class Kind {
        Module, Interface, Struct, Union, Enum, Enumerator, Typedef, Const, Exception, Native, Operation,
        Attribute
    };

    Kind kind = Kind::Module;
    QString scopedName; ///< `RTC::TimedLong`; the parent scope is everything before the last `::`
    IdlSource source;

    /// The enclosing scope's scoped name ("" for the global scope).
    QString parentScope() const;
    /// The last component of the scoped name.
    QString name() const;

    bool operator==(const IdlDeclaration &other) const;
    bool operator!=(const IdlDeclaration &other) const { return !(*this == other); }
};

/// Entry of the "data types" list: a struct usable as a data port type.
struct IdlDataType
{
    QString scopedName;
    bool timed = false; ///< has a member `tm` of type RTC::Time (the OpenRTM rule)
    IdlSource source;

    bool operator==(const IdlDataType &other) const;
    bool operator!=(const IdlDataType &other) const { return !(*this == other); }
};

/// The parsed content of one or more IDL files, keyed by fully scoped names (no leading `::`).
struct IdlModel
{
    QList<IdlDeclaration> declarations; ///< the tree, flattened in declaration order (modules once)
    QMap<QString, IdlStruct> structs;
    QMap<QString, IdlUnion> unions;
    QMap<QString, IdlEnum> enums;
    QMap<QString, IdlTypedef> typedefs;
    QMap<QString, IdlConst> consts;
    QMap<QString, IdlException> exceptions;
    QMap<QString, IdlInterface> interfaces;
    QStringList files; ///< every file read, in reading order
    /// `#pragma prefix` of each file that has one: line → prefix in effect from that line on.
    QMap<QString, QMap<int, QString>> prefixes;

    /// The declaration of `scopedName`, if any.
    std::optional<IdlDeclaration> find(const QString &scopedName) const;
    /// Direct children of a scope ("" = global), in declaration order.
    QList<IdlDeclaration> children(const QString &scope) const;

    /**
     * The type id of `scopedName`: `IDL:Mod/Name:1.0`, or `IDL:acme.com/Mod/Name:1.0` when its file
     * declares it after `#pragma prefix "acme.com"`.
     */
    QString repositoryId(const QString &scopedName) const;
    /// The scoped name whose repositoryId() is @p repositoryId (`Mod::Name`); empty when none is.
    QString scopedNameOf(const QString &repositoryId) const;

    /// Follows typedefs (and value boxes) until the type is no typedef; stops on cycles.
    IdlType resolve(const IdlType &type) const;
    /// The typedef names passed through when resolving `scopedName`, starting with itself.
    QStringList typedefChain(const QString &scopedName) const;

    /// True when the struct has a `tm` member whose type resolves to RTC::Time.
    bool isTimed(const IdlStruct &type) const;
    /// All structs as data port type candidates, sorted by scoped name, timed ones flagged.
    QList<IdlDataType> dataTypes() const;
    /// Defined (not only forward-declared) interfaces sorted by scoped name.
    QList<IdlInterface> definedInterfaces() const;
    /// All base interfaces of `scopedName`, transitively, each once, nearest first.
    QStringList allBases(const QString &scopedName) const;
    /// Operations of the interface and of all its bases (bases' first, each interface once).
    QList<IdlOperation> allOperations(const QString &scopedName) const;
    /// Attributes of the interface and of all its bases.
    QList<IdlAttribute> allAttributes(const QString &scopedName) const;

    bool operator==(const IdlModel &other) const;
    bool operator!=(const IdlModel &other) const { return !(*this == other); }
};

} // namespace Codegen
