// SPDX-License-Identifier: MIT
#include <coil/Properties.h>
#include <coil/stringutil.h>

#include <algorithm>
#include <istream>
#include <ostream>

namespace coil {
namespace {
bool isBlankKey(const std::string &key)
{
    return eraseBothEndsBlank(key).empty();
}

// Node names go back through load(), which unescapes keys, splits at ':' and '=', and
// takes a line starting with '#' or '!' for a comment.
std::string escapeKeyPart(const std::string &name)
{
    std::string out;
    for (char c : escape(name)) {
        if (c == ':' || c == '=' || c == '#' || c == '!')
            out += '\\';
        out += c;
    }
    return out;
}
} // namespace

Properties::Properties(const char *key, const char *value, bool set_value)
    : m_name(key != nullptr ? key : "")
    , m_value(value != nullptr ? value : "")
    , m_setValue(!m_value.empty() || set_value)
    , m_root(nullptr)
{ }

Properties::Properties(std::map<std::string, std::string> &defaults)
    : m_setValue(false)
    , m_root(nullptr)
{
    for (const auto &entry : defaults)
        setDefault(entry.first, entry.second);
}

Properties::Properties(const char *const defaults[], size_t num)
    : m_setValue(false)
    , m_root(nullptr)
{
    setDefaults(defaults, num);
}

Properties::Properties(const Properties &prop)
    : m_name(prop.m_name)
    , m_value(prop.m_value)
    , m_defaultValue(prop.m_defaultValue)
    , m_setValue(prop.m_setValue)
    , m_root(nullptr)
{
    copyChildrenFrom(prop);
}

Properties &Properties::operator=(const Properties &prop)
{
    if (&prop == this)
        return *this;
    // Copy first: prop may be one of our own descendants, which clear() deletes.
    Properties copy(prop);
    clear();
    if (m_root == nullptr)
        m_name = copy.m_name;
    m_value = copy.m_value;
    m_defaultValue = copy.m_defaultValue;
    m_setValue = copy.m_setValue;
    m_leaf.swap(copy.m_leaf);
    for (Properties *child : m_leaf)
        child->m_root = this;
    return *this;
}

Properties::~Properties()
{
    clear();
    if (m_root != nullptr)
        m_root->detachChild(this);
}

void Properties::copyChildrenFrom(const Properties &prop)
{
    for (const Properties *child : prop.m_leaf) {
        Properties *copy = new Properties(*child);
        copy->m_root = this;
        m_leaf.push_back(copy);
    }
}

void Properties::detachChild(const Properties *child)
{
    m_leaf.erase(std::remove(m_leaf.begin(), m_leaf.end(), child), m_leaf.end());
}

Properties *Properties::childNamed(const std::string &name) const
{
    for (Properties *child : m_leaf)
        if (child->m_name == name)
            return child;
    return nullptr;
}

Properties *Properties::makePath(const std::string &key)
{
    std::vector<std::string> parts;
    split(key, '.', parts);
    Properties *node = this;
    for (const std::string &part : parts) {
        Properties *next = node->childNamed(part);
        if (next == nullptr) {
            next = new Properties(part.c_str());
            next->m_root = node;
            node->m_leaf.push_back(next);
        }
        node = next;
    }
    return node;
}

const std::string &Properties::getProperty(const std::string &key) const
{
    const Properties *node = findNode(key);
    if (node == nullptr)
        return m_empty;
    return node->m_setValue ? node->m_value : node->m_defaultValue;
}

const std::string &Properties::getProperty(const std::string &key, const std::string &def) const
{
    const std::string &value = getProperty(key);
    return value.empty() ? def : value;
}

const std::string &Properties::operator[](const std::string &key) const
{
    return getProperty(key);
}

std::string &Properties::operator[](const std::string &key)
{
    if (isBlankKey(key))
        return m_value; // nothing to address below: the node itself
    Properties *node = makePath(key);
    if (!node->m_setValue) {
        node->m_value = node->m_defaultValue;
        node->m_setValue = true;
    }
    return node->m_value;
}

const std::string &Properties::getDefault(const std::string &key) const
{
    const Properties *node = findNode(key);
    return node != nullptr ? node->m_defaultValue : m_empty;
}

std::string Properties::setProperty(const std::string &key, const std::string &invalue)
{
    if (isBlankKey(key))
        return std::string();
    Properties *node = makePath(key);
    std::string previous = node->m_value;
    node->m_value = invalue;
    node->m_setValue = true;
    return previous;
}

std::string Properties::setDefault(const std::string &key, const std::string &invalue)
{
    if (isBlankKey(key))
        return std::string();
    makePath(key)->m_defaultValue = invalue;
    return invalue;
}

void Properties::setDefaults(const char *const defaults[], size_t num)
{
    if (defaults == nullptr)
        return;
    for (size_t i = 0; i < num; i += 2) {
        const char *key = defaults[i];
        if (key == nullptr || key[0] == '\0')
            return;
        const char *value = (i + 1 < num) ? defaults[i + 1] : nullptr;
        if (value == nullptr)
            return;
        setDefault(eraseBothEndsBlank(key), eraseBothEndsBlank(value));
    }
}

void Properties::list(std::ostream &out)
{
    _store(out, "", this);
}

void Properties::load(std::istream &inStream)
{
    // As in OpenRTM-aist, blank and comment lines are skipped even between the lines of a
    // continued entry, so a commented-out item inside a long list does not end the list.
    std::string pending;
    while (inStream.good()) {
        std::string line = eraseHeadBlank(getlinePortable(inStream));
        if (line.empty() || line[0] == '#' || line[0] == '!')
            continue;
        if (line.back() == '\\' && !isEscaped(line, line.size() - 1)) {
            line.pop_back();
            pending += line;
            continue;
        }
        pending += line;
        loadEntry(pending);
        pending.clear();
    }
    loadEntry(pending); // a backslash on the last line continues into nothing
}

void Properties::loadEntry(const std::string &entry)
{
    if (eraseBothEndsBlank(entry).empty())
        return;
    std::string key, value;
    splitKeyValue(entry, key, value);
    setProperty(eraseBothEndsBlank(unescape(key)), eraseBothEndsBlank(unescape(value)));
}

void Properties::save(std::ostream &out, const std::string &header)
{
    store(out, header);
}

void Properties::store(std::ostream &out, const std::string &header)
{
    out << "# " << header << std::endl;
    _store(out, "", this);
}

std::vector<std::string> Properties::propertyNames() const
{
    std::vector<std::string> names;
    for (const Properties *child : m_leaf)
        _propertyNames(names, child->m_name, child);
    return names;
}

size_t Properties::size() const
{
    return propertyNames().size();
}

Properties *Properties::findNode(const std::string &key) const
{
    if (isBlankKey(key))
        return nullptr;
    std::vector<std::string> parts;
    split(key, '.', parts);
    return _getNode(parts, 0, this);
}

Properties &Properties::getNode(const std::string &key)
{
    if (isBlankKey(key))
        return *this;
    if (Properties *node = findNode(key))
        return *node;
    createNode(key);
    return *findNode(key);
}

bool Properties::createNode(const std::string &key)
{
    if (isBlankKey(key) || findNode(key) != nullptr)
        return false;
    (*this)[key] = "";
    return true;
}

Properties *Properties::removeNode(const char *leaf_name)
{
    if (leaf_name == nullptr)
        return nullptr;
    Properties *child = childNamed(leaf_name);
    if (child == nullptr)
        return nullptr;
    detachChild(child);
    child->m_root = nullptr;
    return child;
}

Properties *Properties::hasKey(const char *key) const
{
    if (key == nullptr || isBlankKey(key))
        return nullptr;
    return childNamed(key);
}

void Properties::clear()
{
    // Each child's destructor unlinks it from m_leaf.
    while (!m_leaf.empty())
        delete m_leaf.back();
}

Properties &Properties::operator<<(const Properties &prop)
{
    if (&prop == this)
        return *this;
    for (const std::string &key : prop.propertyNames())
        (*this)[key] = prop[key];
    return *this;
}

Properties::operator std::vector<std::string>() const
{
    std::vector<std::string> lines;
    _dump(lines, *this, 0);
    return lines;
}

void Properties::_dump(std::string &out, const Properties &curr, size_t index) const
{
    std::vector<std::string> lines;
    _dump(lines, curr, index);
    for (const std::string &line : lines)
        out += line + "\n";
}

void Properties::_dump(std::vector<std::string> &out, const Properties &curr, size_t index) const
{
    std::string head = index != 0 ? indent(index) + "- " + curr.m_name : std::string();
    if (curr.m_leaf.empty()) {
        out.push_back(head + ": " + (curr.m_setValue ? curr.m_value : curr.m_defaultValue));
        return;
    }
    if (index != 0)
        out.push_back(head);
    for (const Properties *child : curr.m_leaf)
        _dump(out, *child, index + 1);
}

void Properties::splitKeyValue(const std::string &str, std::string &key, std::string &value)
{
    std::string::size_type at = std::string::npos;
    for (std::string::size_type i = 0; i < str.size(); ++i)
        if ((str[i] == ':' || str[i] == '=') && !isEscaped(str, i)) {
            at = i;
            break;
        }
    if (at == std::string::npos)
        for (std::string::size_type i = 0; i < str.size(); ++i)
            if ((str[i] == ' ' || str[i] == '\t') && !isEscaped(str, i)) {
                at = i;
                break;
            }
    if (at == std::string::npos) {
        key = str;
        value.clear();
        return;
    }
    key = eraseBothEndsBlank(str.substr(0, at));
    value = eraseBothEndsBlank(str.substr(at + 1));
}

bool Properties::split(const std::string &str, char delim, std::vector<std::string> &value)
{
    if (str.empty())
        return false;
    std::string::size_type begin = 0;
    for (std::string::size_type i = 0; i < str.size(); ++i)
        if (str[i] == delim && !isEscaped(str, i)) {
            value.push_back(str.substr(begin, i - begin));
            begin = i + 1;
        }
    value.push_back(str.substr(begin));
    return true;
}

Properties *Properties::_getNode(std::vector<std::string> &keys,
                                 std::vector<Properties *>::size_type index, const Properties *curr)
{
    Properties *node = nullptr;
    for (; curr != nullptr && index < keys.size(); ++index) {
        node = curr->childNamed(keys[index]);
        curr = node;
    }
    return node;
}

void Properties::_propertyNames(std::vector<std::string> &names, const std::string &curr_name,
                                const Properties *curr)
{
    if (curr->m_leaf.empty()) {
        names.push_back(curr_name);
        return;
    }
    for (const Properties *child : curr->m_leaf)
        _propertyNames(names, curr_name + "." + child->m_name, child);
}

void Properties::_store(std::ostream &out, const std::string &curr_name, Properties *curr)
{
    // An empty curr_name marks the node list() starts from, which is not written itself.
    storeBelow(out, curr_name.empty() ? std::string() : curr_name + ".", curr);
    if (curr->m_root != nullptr && curr->m_setValue && !curr_name.empty())
        out << curr_name << ": " << escape(curr->m_value) << std::endl;
}

void Properties::storeBelow(std::ostream &out, const std::string &prefix, const Properties *curr)
{
    for (const Properties *child : curr->m_leaf) {
        const std::string key = prefix + escapeKeyPart(child->m_name);
        storeBelow(out, key + ".", child);
        if (child->m_setValue && !key.empty())
            out << key << ": " << escape(child->m_value) << std::endl;
    }
}

std::ostream &Properties::_dump(std::ostream &out, const Properties &curr, size_t index)
{
    std::vector<std::string> lines;
    curr._dump(lines, curr, index);
    for (const std::string &line : lines)
        out << line << std::endl;
    return out;
}

std::string Properties::indent(size_t index)
{
    return index > 1 ? std::string(2 * (index - 1), ' ') : std::string();
}

std::ostream &operator<<(std::ostream &lhs, const Properties &rhs)
{
    return Properties::_dump(lhs, rhs, 0);
}
} // namespace coil
