// SPDX-License-Identifier: MIT
/*!
 * @file Properties.h
 * @brief coil::Properties: a tree of string values addressed by dotted keys ("a.b.c").
 */
#ifndef COIL_PROPERTIES_H
#define COIL_PROPERTIES_H

#include <climits>
#include <cstddef>
#include <iosfwd>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace coil {
/*!
 * A property tree, as used for rtc.conf, component profiles and configuration sets.
 *
 * Each node has a name, a value and a default value. A key such as "conf.default.gain" is
 * split at each '.' that is not escaped by a backslash and names a path from this node
 * down. Reading a key gives the value when one was set, otherwise the default value.
 * Nodes own their children.
 */
class Properties
{
public:
    /*!
     * A single node named @p key holding @p value. The value counts as set when it is not
     * empty, or when @p set_value is true.
     */
    explicit Properties(const char *key = "", const char *value = "", bool set_value = false);
    /*! A root whose default values come from the key/value pairs of @p defaults. */
    explicit Properties(std::map<std::string, std::string> &defaults);
    /*!
     * A root whose default values come from @p defaults: key, value, key, value, ... ended by
     * an empty string, or after @p num entries. Blanks around keys and values are removed.
     */
    explicit Properties(const char *const defaults[],
                        size_t num = (std::numeric_limits<size_t>::max)());
    /*! A deep copy of @p prop (the copy has no parent). */
    Properties(const Properties &prop);
    /*!
     * Replaces this node's value, default and children by deep copies of @p prop's. A node
     * that is inside a tree keeps its own name, so the tree can still find it.
     */
    Properties &operator=(const Properties &prop);
    /*! Deletes the children and unlinks this node from its parent. */
    virtual ~Properties();

    /*! The node's own name (the last part of its key). */
    const char *getName() const { return m_name.c_str(); }
    /*! The node's own value. */
    const char *getValue() const { return m_value.c_str(); }
    /*! The node's own default value. */
    const char *getDefaultValue() const { return m_defaultValue.c_str(); }
    /*! The child nodes, in insertion order. */
    const std::vector<Properties *> &getLeaf() const { return m_leaf; }
    /*! The parent node, or null for a root. */
    const Properties *getRoot() const { return m_root; }

    /*! The value under @p key (its default when no value was set; "" when absent). */
    const std::string &getProperty(const std::string &key) const;
    /*! The value under @p key, or @p def when that is empty. */
    const std::string &getProperty(const std::string &key, const std::string &def) const;
    /*! Same as getProperty(key). */
    const std::string &operator[](const std::string &key) const;
    /*!
     * The value under @p key for writing; the node is created when missing and marked as set,
     * starting from the value getProperty(key) gave.
     */
    std::string &operator[](const std::string &key);
    /*! The default value under @p key ("" when absent). */
    const std::string &getDefault(const std::string &key) const;
    /*! Sets the value under @p key, creating nodes as needed; returns the previous value. */
    std::string setProperty(const std::string &key, const std::string &invalue);
    /*! Sets the default value under @p key, creating nodes as needed; returns @p invalue. */
    std::string setDefault(const std::string &key, const std::string &invalue);
    /*! Sets default values from a key/value array, as the array constructor does. */
    void setDefaults(const char *const defaults[],
                     size_t num = (std::numeric_limits<size_t>::max)());

    /*! Writes every set value as "key: value" lines. */
    void list(std::ostream &out);
    /*!
     * Reads "key: value", "key = value" or "key value" lines. Lines starting with '#' or '!'
     * are comments; a line ending in an unescaped backslash continues on the next line;
     * backslash escapes in keys and values are decoded. Loaded values are set values.
     */
    void load(std::istream &inStream);
    /*! Same as store(). */
    void save(std::ostream &out, const std::string &header);
    /*! Writes "# header" and then the list() lines. */
    void store(std::ostream &out, const std::string &header);

    /*! The full keys of all nodes that have no children. */
    std::vector<std::string> propertyNames() const;
    /*! The number of propertyNames(). */
    size_t size() const;
    /*! The node under @p key, or null. */
    Properties *findNode(const std::string &key) const;
    /*! The node under @p key, created when missing; this node for an empty key. */
    Properties &getNode(const std::string &key);
    /*! Creates the node under @p key; false if it exists or @p key is empty. */
    bool createNode(const std::string &key);
    /*!
     * Unlinks the direct child named @p leaf_name and returns it (the caller then owns it),
     * or returns null.
     */
    Properties *removeNode(const char *leaf_name);
    /*! The direct child named @p key, or null. */
    Properties *hasKey(const char *key) const;
    /*! Deletes all children. */
    void clear();
    /*! Sets every property of @p prop in this tree (values win over existing ones). */
    Properties &operator<<(const Properties &prop);
    /*! The tree as indented "- name: value" lines, one string per line. */
    operator std::vector<std::string>() const;

    /*! Appends the indented dump of @p curr (see operator<<(std::ostream&, ...)) to @p out. */
    void _dump(std::string &out, const Properties &curr, size_t index) const;
    /*! Appends the indented dump of @p curr to @p out, one string per line. */
    void _dump(std::vector<std::string> &out, const Properties &curr, size_t index) const;

protected:
    /*! Splits a "key: value" line at its first unescaped ':' or '=' (else at a blank). */
    static void splitKeyValue(const std::string &str, std::string &key, std::string &value);
    /*! Splits @p str at each unescaped @p delim, appending the parts to @p value. */
    static bool split(const std::string &str, char delim, std::vector<std::string> &value);
    /*! Follows @p keys from @p index below @p curr; null when a part is missing. */
    static Properties *_getNode(std::vector<std::string> &keys,
                                std::vector<Properties *>::size_type index, const Properties *curr);
    /*! Collects the full names of the childless nodes below @p curr. */
    static void _propertyNames(std::vector<std::string> &names, const std::string &curr_name,
                               const Properties *curr);
    /*! Writes the set values below @p curr as "key: value" lines. */
    static void _store(std::ostream &out, const std::string &curr_name, Properties *curr);
    /*! Writes the indented dump of @p curr. */
    static std::ostream &_dump(std::ostream &out, const Properties &curr, size_t index);
    /*! Two blanks per level below the first. */
    static std::string indent(size_t index);

private:
    static void storeBelow(std::ostream &out, const std::string &prefix, const Properties *curr);
    void loadEntry(const std::string &entry);
    Properties *childNamed(const std::string &name) const;
    Properties *makePath(const std::string &key);
    void copyChildrenFrom(const Properties &prop);
    void detachChild(const Properties *child);

    std::string m_name;
    std::string m_value;
    std::string m_defaultValue;
    bool m_setValue;
    Properties *m_root;
    std::vector<Properties *> m_leaf;
    const std::string m_empty;

    friend std::ostream &operator<<(std::ostream &lhs, const Properties &rhs);
};

/*! Writes @p rhs as an indented tree of "- name: value" lines. */
std::ostream &operator<<(std::ostream &lhs, const Properties &rhs);
} // namespace coil

#endif // COIL_PROPERTIES_H
