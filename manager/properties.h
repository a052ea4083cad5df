// SPDX-License-Identifier: MIT
#pragma once

#include <chrono>
#include <map>
#include <string>
#include <vector>

namespace Runtime {

/**
 * Flat OpenRTM-style key/value properties ("a.b.c" → "value"), as read from rtc.conf, passed to
 * create_component and kept by components and managers. Keys keep their text; order is by key.
 */
class Properties
{
public:
    /// Value of @p key, or @p fallback when the key is absent.
    std::string value(const std::string &key, const std::string &fallback = {}) const;
    bool contains(const std::string &key) const;
    void set(const std::string &key, const std::string &value);
    void remove(const std::string &key);
    /// Copies every entry of @p other over this one.
    void merge(const Properties &other);
    /// Entries below "prefix." with the prefix taken off.
    Properties subtree(const std::string &prefix) const;
    /// True when the value of @p key is YES/TRUE/1/ON (any case); @p fallback when absent.
    bool isYes(const std::string &key, bool fallback = false) const;
    /// The value of @p key as a number; @p fallback when absent or empty. A value that is not a
    /// number (or not all of one) also gives @p fallback and is described in @p problem.
    double number(const std::string &key, double fallback, std::string *problem = nullptr) const;
    const std::map<std::string, std::string> &entries() const { return m_entries; }

    /**
     * Reads rtc.conf text: `key: value` or `key = value` lines, `#` comments, a trailing backslash
     * continues a line. Malformed lines are reported in @p errors ("LINE: message").
     */
    static Properties parseConf(const std::string &text, std::vector<std::string> *errors = nullptr);

private:
    std::map<std::string, std::string> m_entries;
};

/**
 * @p seconds as a clock's duration for a wait: negative (or not a number) is 0, and more than about
 * 30 years is 30 years, so that adding it to the clock's time cannot overflow.
 */
std::chrono::steady_clock::duration boundedSeconds(double seconds);

/// Trims ASCII white space at both ends.
std::string trimmed(const std::string &text);
/// Splits at @p separator; with @p skipEmpty, trimmed empty parts are dropped.
std::vector<std::string> split(const std::string &text, char separator, bool skipEmpty = true);
/**
 * Splits a command line as OpenRTM-aist's coil::parseArgs does (corba.args, manager_cmd): blanks
 * separate arguments unless quoted ('…' or "…") or escaped; an empty text gives one empty argument.
 */
std::vector<std::string> splitArguments(const std::string &args);
/**
 * A composite's `exported_ports` list as OpenRTM-aist's manager and SDO configuration store it:
 * comma-separated `<instance>.<port>` names, where a longer dotted name keeps its first and last
 * parts (names written before ports carried their instance's name).
 */
std::string exportedPortList(const std::string &text);

} // namespace Runtime
