// SPDX-License-Identifier: MIT
#pragma once

#include "xmlnode.h"

#include <QHash>
#include <QString>

#include <functional>

/**
 * How to compare a saved file with the file it was loaded from: which legacy names stand for which
 * schema names, and how to normalise values that may be written differently but mean the same.
 *
 * Names are given as "{namespaceUri}localName".
 */
struct XmlNormalization
{
    /// Legacy element name → schema element name.
    QHash<QString, QString> elementRenames;
    /// Legacy attribute name → schema attribute name (qualified by the namespace it is read in).
    QHash<QString, QString> attributeRenames;
    /// Attribute name (after renaming) → value normaliser.
    QHash<QString, std::function<QString(const QString &)>> valueNormalizers;
    /// Elements whose presence alone carries nothing (e.g. an empty optional wrapper) are
    /// dropped when they have no attributes and no children.
    QHash<QString, bool> dropWhenEmpty;
    /// Attribute names (after renaming) that the writer may add with a default value
    /// (mapped to that default); an absent attribute is compared as if it had this value.
    QHash<QString, QString> defaultedAttributes;

    static QString key(const QString &namespaceUri, const QString &localName)
    {
        return QLatin1Char('{') + namespaceUri + QLatin1Char('}') + localName;
    }

    /// Upper-cases the value (for enums that old files write in lower case).
    static QString upperCase(const QString &value) { return value.toUpper(); }
    /// Maps xs:boolean spellings to true/false; leaves anything else as it is.
    static QString boolean(const QString &value);
    /// Compares numbers by value ("1000.0" == "1000"); leaves non-numbers as they are.
    static QString number(const QString &value);
};

/**
 * Compares two element trees as documents: attribute order, prefixes, whitespace, xsi:type and the
 * order of sibling elements do not matter; names, attribute values and text do.
 *
 * @return an empty string when they are equivalent, otherwise a description of one difference
 *         with the path to it.
 */
QString xmlDifference(const Profile::XmlNode &expected, const Profile::XmlNode &actual,
                      const XmlNormalization &normalization = {});
