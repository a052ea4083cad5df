// SPDX-License-Identifier: MIT
/*!
 * @file stringutil.h
 * @brief coil's string helpers: trimming, splitting, escaping and text-to-value conversion.
 *
 * The signatures follow OpenRTM-aist 2.x. Where 1.x changed its argument in place (toLower,
 * eraseBlank, replaceString, ...) 2.x returns a new string instead; those functions warn when
 * their result is ignored, which is how a 1.x-style call shows up.
 */
#ifndef COIL_STRINGUTIL_H
#define COIL_STRINGUTIL_H

#include <coil/config_coil.h>

#include <cassert>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <istream>
#include <map>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

/*!
 * The stream coil converts through (stringTo, otos). It lives in the global namespace on
 * purpose: argument-dependent lookup then also searches the global namespace, so a stream
 * operator a component declares there (as in OpenRTP's VectorConvert.h, for std::vector) is
 * found even when it is declared after this header.
 */
class coil_conversion_stream : public std::stringstream
{
};

namespace coil {
/*! A list of strings. */
typedef std::vector<std::string> vstring;
/*! A string-to-string map. */
typedef std::map<std::string, std::string> mapstring;

/*! Widens each byte of @p str to a wide character (no multibyte decoding). */
std::wstring string2wstring(const std::string &str);
/*! Narrows each wide character of @p wstr to one byte. */
std::string wstring2string(const std::wstring &wstr);

/*! Returns @p str in upper case (ASCII letters). */
COIL_WARN_UNUSED_RESULT std::string toUpper(std::string str) noexcept;
/*! Returns @p str in lower case (ASCII letters). */
COIL_WARN_UNUSED_RESULT std::string toLower(std::string str) noexcept;

/*! Reads one line ending in LF, CR or CR LF and returns it without the line end. */
std::string getlinePortable(std::istream &istr);
/*! 1.x form: reads one line into @p line and returns its length. */
int getlinePortable(std::istream &istr, std::string &line);

/*! True if the character at @p pos is preceded by an odd number of backslashes. */
bool isEscaped(const std::string &str, std::string::size_type pos);
/*! Writes tab, newline, form feed, carriage return and backslash as backslash sequences. */
std::string escape(const std::string &str);
/*! Turns backslash sequences back into characters; an unknown "\x" becomes "x". */
std::string unescape(std::string str) noexcept;

/*! Removes every space and tab. */
COIL_WARN_UNUSED_RESULT std::string eraseBlank(std::string str) noexcept;
/*! Removes spaces and tabs at the start. */
COIL_WARN_UNUSED_RESULT std::string eraseHeadBlank(std::string str) noexcept;
/*! Removes spaces and tabs at the end. */
COIL_WARN_UNUSED_RESULT std::string eraseTailBlank(std::string str) noexcept;
/*! Removes spaces and tabs at both ends. */
COIL_WARN_UNUSED_RESULT std::string eraseBothEndsBlank(std::string str) noexcept;
/*! Same as eraseBothEndsBlank(). */
COIL_WARN_UNUSED_RESULT std::string eraseBothEnds(std::string str) noexcept;
/*! Trims blanks at both ends and lowers the case. */
COIL_WARN_UNUSED_RESULT std::string normalize(std::string str) noexcept;
/*! Replaces every occurrence of @p from by @p to (nothing happens when @p from is empty). */
COIL_WARN_UNUSED_RESULT std::string replaceString(std::string str, const std::string &from,
                                                  const std::string &to);

/*!
 * Splits @p input at each @p delimiter and trims blanks around each piece. Empty input gives
 * an empty list; with @p ignore_empty, empty pieces are dropped.
 */
vstring split(const std::string &input, const std::string &delimiter, bool ignore_empty = false);

/*!
 * True if @p str contains @p yes, false if it contains @p no (both case-insensitive),
 * otherwise @p default_value.
 */
bool toBool(std::string str, std::string yes, std::string no, bool default_value = true);

/*! True if @p list contains @p value. */
bool includes(const vstring &list, std::string value, bool ignore_case = true);
/*! True if the comma-separated @p list contains @p value. */
bool includes(const std::string &list, std::string value, bool ignore_case = true);

/*! True for "/x", "C:\x", "C:/x" and "\\host\x". */
bool isAbsolutePath(const std::string &str);
/*! True if @p str contains "<word character>://". */
bool isURL(const std::string &str);
/*! True for a dotted-decimal IPv4 address (four numbers 0-255). */
bool isIPv4(const std::string &str);
/*! True for a full IPv6 address of eight hexadecimal groups. */
bool isIPv6(const std::string &str);
/*! True for a decimal port number 0-65535. */
bool isIPPort(const std::string &str);

/*! Reads "a=1&b=2" (after a '?', if any) into a map. */
mapstring urlparam2map(const std::string &str);
/*! Splits a command line at blanks, honouring quotes and backslash escapes. */
vstring parseArgs(const std::string &args);

namespace detail {
// True when a failed read can go to a fresh value instead of the caller's variable.
template<typename T>
struct CanReadIntoCopy
    : std::integral_constant<
          bool, std::is_default_constructible<T>::value && std::is_copy_assignable<T>::value>
{
};

template<typename To> bool readInto(coil_conversion_stream &stream, To &val, std::true_type)
{
    To result = To();
    if ((stream >> result).fail()) {
        return false;
    }
    val = result;
    return true;
}

template<typename To> bool readInto(coil_conversion_stream &stream, To &val, std::false_type)
{
    return !(stream >> val).fail();
}
} // namespace detail

/*! Writes @p n to a string with operator<<. */
template<class Printable> std::string otos(Printable n)
{
    coil_conversion_stream stream;
    stream << n;
    return stream.str();
}

/*!
 * Reads @p str into @p val with operator>>. Returns false (and leaves @p val unchanged) when
 * @p str is null or cannot be read as the type.
 */
template<typename To> bool stringTo(To &val, const char *str)
{
    if (str == 0) {
        return false;
    }
    coil_conversion_stream stream;
    stream << str;
    return detail::readInto(stream, val, detail::CanReadIntoCopy<To>());
}

/*! Copies the whole text, blanks included. */
template<> bool stringTo<std::string>(std::string &val, const char *str);
/*! Accepts true/false, 1/0, yes/no, on/off in any case, blanks around ignored. */
template<> bool stringTo<bool>(bool &val, const char *str);
/*! Reads seconds as a decimal number. */
template<>
bool stringTo<std::chrono::duration<double>>(std::chrono::duration<double> &val, const char *str);
/*! Reads seconds as a decimal number. */
template<> bool stringTo<std::chrono::nanoseconds>(std::chrono::nanoseconds &val, const char *str);
/*! Reads seconds as a decimal number. */
template<>
bool stringTo<std::chrono::microseconds>(std::chrono::microseconds &val, const char *str);
/*! Reads seconds as a decimal number. */
template<>
bool stringTo<std::chrono::milliseconds>(std::chrono::milliseconds &val, const char *str);
/*! Reads seconds as a decimal number. */
template<> bool stringTo<std::chrono::seconds>(std::chrono::seconds &val, const char *str);
/*! Reads seconds as a decimal number. */
template<> bool stringTo<std::chrono::minutes>(std::chrono::minutes &val, const char *str);
/*! Reads seconds as a decimal number. */
template<> bool stringTo<std::chrono::hours>(std::chrono::hours &val, const char *str);

/*! Writes a pointer as "0x..." text. */
template<class T> std::string ptrToHex(T *n)
{
    std::stringstream stream;
    stream << std::hex << std::showbase << reinterpret_cast<std::uintptr_t>(n);
    return stream.str();
}

/*! Reads a pointer written by ptrToHex(); false for bad text or a null pointer. */
template<class T> bool hexToPtr(T *&ptr, const std::string &str)
{
    std::stringstream stream(str);
    std::uintptr_t address = 0;
    if ((stream >> std::hex >> address).fail()) {
        return false;
    }
    ptr = reinterpret_cast<T *>(address);
    return ptr != 0;
}

/*! Returns the strings of @p sv with duplicates removed. */
vstring unique_sv(vstring sv);
/*! Joins @p sv with @p delimiter between the items. */
std::string flatten(vstring sv, const std::string &delimiter = ", ");

/*!
 * 1.x: a null-terminated argv copy of @p args, allocated with new[]; the caller owns the
 * array and each string. Prefer coil::Argv, which frees itself.
 */
char **toArgv(const vstring &args);

/*! An argv-style array built from strings, owning its memory. */
class Argv
{
public:
    Argv();
    /*! Copies @p args; get() then returns them followed by a null pointer. */
    explicit Argv(const vstring &args);
    Argv(Argv &&other);
    Argv &operator=(Argv &&other);
    ~Argv();
    /*! The arguments for main()-style functions, or null when there are none. */
    char **get() { return size() == 0 ? 0 : &m_argv[0]; }
    /*! Number of arguments. */
    size_t size() const { return m_args.size(); }

private:
    Argv(const Argv &);
    Argv &operator=(const Argv &);
    std::vector<char *> m_argv;
    std::vector<std::vector<char>> m_args;
};

/*!
 * printf-style formatting into a std::string (no length limit). Deliberately without a
 * format attribute: RTC_INFO(("...")) in existing components must stay warning-free.
 */
std::string sprintf(char const *fmt, ...);

/*! Replaces each "${NAME}" by the environment variable NAME (empty when unset). */
std::string replaceEnv(std::string str);
} // namespace coil

#endif // COIL_STRINGUTIL_H
