// SPDX-License-Identifier: MIT
#include "properties.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace Runtime {

std::string trimmed(const std::string &text)
{
    const auto isSpace = [](unsigned char c) { return std::isspace(c) != 0; };
    auto begin = std::find_if_not(text.begin(), text.end(), isSpace);
    auto end = std::find_if_not(text.rbegin(), std::string::const_reverse_iterator(begin), isSpace).base();
    return std::string(begin, end);
}

std::vector<std::string> split(const std::string &text, char separator, bool skipEmpty)
{
    std::vector<std::string> parts;
    std::string part;
    std::istringstream stream(text);
    while (std::getline(stream, part, separator)) {
        part = trimmed(part);
        if (!skipEmpty || !part.empty())
            parts.push_back(part);
    }
    if (!skipEmpty && !text.empty() && text.back() == separator)
        parts.emplace_back();
    return parts;
}

std::string Properties::value(const std::string &key, const std::string &fallback) const
{
    auto it = m_entries.find(key);
    return it == m_entries.end() ? fallback : it->second;
}

bool Properties::contains(const std::string &key) const
{
    return m_entries.count(key) != 0;
}

void Properties::set(const std::string &key, const std::string &value)
{
    m_entries[key] = value;
}

void Properties::remove(const std::string &key)
{
    m_entries.erase(key);
}

void Properties::merge(const Properties &other)
{
    for (const auto &[key, value] : other.m_entries)
        m_entries[key] = value;
}

Properties Properties::subtree(const std::string &prefix) const
{
    Properties result;
    const std::string dotted = prefix + '.';
    for (auto it = m_entries.lower_bound(dotted); it != m_entries.end(); ++it) {
        if (it->first.compare(0, dotted.size(), dotted) != 0)
            break;
        result.m_entries[it->first.substr(dotted.size())] = it->second;
    }
    return result;
}

bool Properties::isYes(const std::string &key, bool fallback) const
{
    auto it = m_entries.find(key);
    if (it == m_entries.end())
        return fallback;
    std::string v = trimmed(it->second);
    std::transform(v.begin(), v.end(), v.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    return v == "YES" || v == "TRUE" || v == "1" || v == "ON";
}

double Properties::number(const std::string &key, double fallback, std::string *problem) const
{
    auto it = m_entries.find(key);
    const std::string text = it == m_entries.end() ? std::string() : trimmed(it->second);
    if (text.empty())
        return fallback;
    char *end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0' || !std::isfinite(value)) {
        if (problem) {
            std::ostringstream message;
            message << key << ": '" << text << "' is not a number; " << fallback << " is used";
            *problem = message.str();
        }
        return fallback;
    }
    return value;
}

std::chrono::steady_clock::duration boundedSeconds(double seconds)
{
    constexpr double longest = 1e9;
    const double bounded = seconds > 0.0 ? std::min(seconds, longest) : 0.0;
    return std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(bounded));
}

Properties Properties::parseConf(const std::string &text, std::vector<std::string> *errors)
{
    Properties result;
    std::istringstream stream(text);
    std::string line;
    std::string pending;
    int lineNumber = 0;
    while (std::getline(stream, line)) {
        ++lineNumber;
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        // OpenRTM's rtc.conf lets a trailing backslash join the next line.
        if (!line.empty() && line.back() == '\\') {
            pending += line.substr(0, line.size() - 1);
            continue;
        }
        const std::string full = trimmed(pending + line);
        pending.clear();
        if (full.empty() || full[0] == '#' || full[0] == '!')
            continue;
        const size_t sep = full.find_first_of(":=");
        if (sep == std::string::npos || sep == 0) {
            if (errors)
                errors->push_back(std::to_string(lineNumber) + ": expected 'key: value', got '" + full + "'");
            continue;
        }
        result.set(trimmed(full.substr(0, sep)), trimmed(full.substr(sep + 1)));
    }
    return result;
}

std::string exportedPortList(const std::string &text)
{
    std::string list;
    for (const std::string &entry : split(text, ',')) {
        const std::string name = trimmed(entry);
        const std::size_t first = name.find('.');
        const std::size_t last = name.rfind('.');
        if (!list.empty())
            list += ',';
        list += first != last ? name.substr(0, first) + name.substr(last) : name;
    }
    return list;
}

std::vector<std::string> splitArguments(const std::string &args)
{
    // Blanks separate arguments unless quoted or escaped; quotes are removed, and a
    // backslash inside quotes is kept unless it escapes the other quote character.
    std::vector<std::string> out;
    std::string current;
    bool inArg = false, escaped = false;
    char quote = 0;
    for (char c : args) {
        if (escaped) {
            escaped = false;
            if (quote != 0 && c != quote && c != '\\')
                current += '\\';
            current += c;
            inArg = true;
            continue;
        }
        if (c == '\\') {
            escaped = true;
            inArg = true;
            continue;
        }
        if (quote != 0) {
            if (c == quote)
                quote = 0;
            else
                current += c;
            continue;
        }
        if (c == '"' || c == '\'') {
            quote = c;
            inArg = true;
            continue;
        }
        if ((c == ' ' || c == '\t')) {
            if (inArg)
                out.push_back(current);
            current.clear();
            inArg = false;
            continue;
        }
        current += c;
        inArg = true;
    }
    if (inArg || out.empty())
        out.push_back(current);
    return out;
}

} // namespace Runtime
