// SPDX-License-Identifier: MIT
#include <coil/stringutil.h>

#include <properties.h>

#include <algorithm>
#include <cctype>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <regex>
#include <unordered_set>

namespace coil {
namespace {
bool isBlank(char c)
{
    return c == ' ' || c == '\t';
}

template<typename Map> std::string mapChars(std::string str, Map map)
{
    for (char &c : str)
        c = static_cast<char>(map(static_cast<unsigned char>(c)));
    return str;
}
} // namespace

std::wstring string2wstring(const std::string &str)
{
    std::wstring out;
    out.reserve(str.size());
    for (char c : str)
        out.push_back(static_cast<wchar_t>(static_cast<unsigned char>(c)));
    return out;
}

std::string wstring2string(const std::wstring &wstr)
{
    std::string out;
    out.reserve(wstr.size());
    for (wchar_t c : wstr)
        out.push_back(static_cast<char>(c));
    return out;
}

std::string toUpper(std::string str) noexcept
{
    return mapChars(std::move(str), [](unsigned char c) { return std::toupper(c); });
}

std::string toLower(std::string str) noexcept
{
    return mapChars(std::move(str), [](unsigned char c) { return std::tolower(c); });
}

std::string getlinePortable(std::istream &istr)
{
    std::string line;
    char c;
    while (istr.get(c)) {
        if (c == '\n')
            break;
        if (c == '\r') {
            if (istr.peek() == '\n')
                istr.ignore();
            break;
        }
        line.push_back(c);
    }
    return line;
}

int getlinePortable(std::istream &istr, std::string &line)
{
    line = getlinePortable(istr);
    return static_cast<int>(line.size());
}

bool isEscaped(const std::string &str, std::string::size_type pos)
{
    if (pos > str.size())
        pos = str.size();
    std::string::size_type backslashes = 0;
    while (pos > 0 && str[pos - 1] == '\\') {
        ++backslashes;
        --pos;
    }
    return backslashes % 2 == 1;
}

std::string escape(const std::string &str)
{
    std::string out;
    out.reserve(str.size() * 2);
    for (char c : str) {
        switch (c) {
        case '\t':
            out += "\\t";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\f':
            out += "\\f";
            break;
        case '\r':
            out += "\\r";
            break;
        case '\\':
            out += "\\\\";
            break;
        default:
            out += c;
            break;
        }
    }
    return out;
}

std::string unescape(std::string str) noexcept
{
    // Decodes in place (the result is never longer), so nothing can throw.
    std::string::size_type out = 0;
    for (std::string::size_type in = 0; in < str.size(); ++in) {
        char c = str[in];
        if (c == '\\' && in + 1 < str.size()) {
            c = str[++in];
            switch (c) {
            case 't':
                c = '\t';
                break;
            case 'n':
                c = '\n';
                break;
            case 'f':
                c = '\f';
                break;
            case 'r':
                c = '\r';
                break;
            default:
                break;
            }
        } else if (c == '\\') {
            break; // a lone backslash at the end escapes nothing and is dropped
        }
        str[out++] = c;
    }
    str.resize(out);
    return str;
}

std::string eraseBlank(std::string str) noexcept
{
    str.erase(std::remove_if(str.begin(), str.end(), isBlank), str.end());
    return str;
}

std::string eraseHeadBlank(std::string str) noexcept
{
    const auto first = str.find_first_not_of(" \t");
    str.erase(0, first); // npos erases everything
    return str;
}

std::string eraseTailBlank(std::string str) noexcept
{
    const auto last = str.find_last_not_of(" \t");
    str.erase(last == std::string::npos ? 0 : last + 1);
    return str;
}

std::string eraseBothEndsBlank(std::string str) noexcept
{
    return eraseHeadBlank(eraseTailBlank(std::move(str)));
}

std::string eraseBothEnds(std::string str) noexcept
{
    return eraseBothEndsBlank(std::move(str));
}

std::string normalize(std::string str) noexcept
{
    return toLower(eraseBothEndsBlank(std::move(str)));
}

std::string replaceString(std::string str, const std::string &from, const std::string &to)
{
    if (from.empty())
        return str;
    // Continue after the inserted text so that "to" containing "from" cannot loop.
    for (auto pos = str.find(from); pos != std::string::npos; pos = str.find(from, pos + to.size()))
        str.replace(pos, from.size(), to);
    return str;
}

vstring split(const std::string &input, const std::string &delimiter, bool ignore_empty)
{
    vstring pieces;
    if (input.empty())
        return pieces;
    if (delimiter.empty()) {
        pieces.push_back(eraseBothEndsBlank(input));
        return pieces;
    }
    std::string::size_type begin = 0;
    while (true) {
        const auto end = input.find(delimiter, begin);
        std::string piece = eraseBothEndsBlank(input.substr(begin, end - begin));
        if (!(ignore_empty && piece.empty()))
            pieces.push_back(std::move(piece));
        if (end == std::string::npos)
            break;
        begin = end + delimiter.size();
    }
    return pieces;
}

bool toBool(std::string str, std::string yes, std::string no, bool default_value)
{
    const std::string text = toUpper(std::move(str));
    if (text.find(toUpper(std::move(yes))) != std::string::npos)
        return true;
    if (text.find(toUpper(std::move(no))) != std::string::npos)
        return false;
    return default_value;
}

bool includes(const vstring &list, std::string value, bool ignore_case)
{
    if (ignore_case)
        value = toLower(std::move(value));
    return std::any_of(list.begin(), list.end(), [&](const std::string &item) {
        return (ignore_case ? toLower(item) : item) == value;
    });
}

bool includes(const std::string &list, std::string value, bool ignore_case)
{
    return includes(split(list, ","), std::move(value), ignore_case);
}

bool isAbsolutePath(const std::string &str)
{
    if (str.empty())
        return false;
    if (str[0] == '/')
        return true;
    if (str.size() >= 3 && std::isalpha(static_cast<unsigned char>(str[0])) && str[1] == ':'
        && (str[2] == '\\' || str[2] == '/'))
        return true;
    return str.compare(0, 2, "\\\\") == 0;
}

bool isURL(const std::string &str)
{
    static const std::regex url(R"(\w://)");
    return std::regex_search(str, url);
}

bool isIPv4(const std::string &str)
{
    static const std::regex ipv4(R"(((25[0-5]|2[0-4][0-9]|1[0-9][0-9]|[1-9][0-9]|[0-9])\.){3})"
                                 R"((25[0-5]|2[0-4][0-9]|1[0-9][0-9]|[1-9][0-9]|[0-9]))");
    return std::regex_match(str, ipv4);
}

bool isIPv6(const std::string &str)
{
    static const std::regex ipv6("([0-9a-fA-F]{1,4}:){7}[0-9a-fA-F]{1,4}");
    return std::regex_match(str, ipv6);
}

bool isIPPort(const std::string &str)
{
    if (str.empty() || str.size() > 5)
        return false;
    if (!std::all_of(str.begin(), str.end(), [](unsigned char c) { return std::isdigit(c); }))
        return false;
    if (str.size() > 1 && str[0] == '0')
        return false;
    return std::stoi(str) <= 65535;
}

mapstring urlparam2map(const std::string &str)
{
    const auto question = str.find('?');
    const std::string query = question == std::string::npos ? str : str.substr(question + 1);
    mapstring params;
    for (const std::string &param : split(query, "&")) {
        if (param.empty())
            continue;
        const auto equal = param.find('=');
        if (equal == std::string::npos) {
            params[param] = std::string();
            continue;
        }
        const std::string key = param.substr(0, equal);
        if (!eraseBothEndsBlank(key).empty())
            params[key] = param.substr(equal + 1);
    }
    return params;
}

vstring parseArgs(const std::string &args)
{
    return Runtime::splitArguments(args);
}

template<> bool stringTo<std::string>(std::string &val, const char *str)
{
    if (str == nullptr)
        return false;
    val = str;
    return true;
}

template<> bool stringTo<bool>(bool &val, const char *str)
{
    if (str == nullptr)
        return false;
    const std::string text = normalize(str);
    if (text == "true" || text == "1" || text == "yes" || text == "on") {
        val = true;
        return true;
    }
    if (text == "false" || text == "0" || text == "no" || text == "off") {
        val = false;
        return true;
    }
    return false;
}

template<>
bool stringTo<std::chrono::duration<double>>(std::chrono::duration<double> &val, const char *str)
{
    double seconds = 0.0;
    if (!stringTo(seconds, str))
        return false;
    val = std::chrono::duration<double>(seconds);
    return true;
}

namespace {
template<typename Duration> bool secondsTo(Duration &val, const char *str)
{
    std::chrono::duration<double> seconds;
    if (!stringTo(seconds, str))
        return false;
    val = std::chrono::duration_cast<Duration>(seconds);
    return true;
}
} // namespace

template<> bool stringTo<std::chrono::nanoseconds>(std::chrono::nanoseconds &val, const char *str)
{
    return secondsTo(val, str);
}

template<> bool stringTo<std::chrono::microseconds>(std::chrono::microseconds &val, const char *str)
{
    return secondsTo(val, str);
}

template<> bool stringTo<std::chrono::milliseconds>(std::chrono::milliseconds &val, const char *str)
{
    return secondsTo(val, str);
}

template<> bool stringTo<std::chrono::seconds>(std::chrono::seconds &val, const char *str)
{
    return secondsTo(val, str);
}

template<> bool stringTo<std::chrono::minutes>(std::chrono::minutes &val, const char *str)
{
    return secondsTo(val, str);
}

template<> bool stringTo<std::chrono::hours>(std::chrono::hours &val, const char *str)
{
    return secondsTo(val, str);
}

vstring unique_sv(vstring sv)
{
    // Keeps the first occurrence of each string, in the original order.
    std::unordered_set<std::string> seen;
    vstring out;
    for (std::string &s : sv)
        if (seen.insert(s).second)
            out.push_back(std::move(s));
    return out;
}

std::string flatten(vstring sv, const std::string &delimiter)
{
    std::string out;
    for (std::size_t i = 0; i < sv.size(); ++i) {
        if (i != 0)
            out += delimiter;
        out += sv[i];
    }
    return out;
}

char **toArgv(const vstring &args)
{
    char **argv = new char *[args.size() + 1];
    for (std::size_t i = 0; i < args.size(); ++i) {
        argv[i] = new char[args[i].size() + 1];
        std::memcpy(argv[i], args[i].c_str(), args[i].size() + 1);
    }
    argv[args.size()] = nullptr;
    return argv;
}

Argv::Argv() = default;

Argv::Argv(const vstring &args)
{
    m_args.reserve(args.size());
    for (const std::string &arg : args)
        m_args.emplace_back(arg.c_str(), arg.c_str() + arg.size() + 1);
    for (std::vector<char> &arg : m_args)
        m_argv.push_back(arg.data());
    m_argv.push_back(nullptr);
}

Argv::Argv(Argv &&other) = default;
Argv &Argv::operator=(Argv &&other) = default;
Argv::~Argv() = default;

std::string sprintf(char const *fmt, ...)
{
    if (fmt == nullptr)
        return std::string();
    va_list args;
    va_start(args, fmt);
    va_list copy;
    va_copy(copy, args);
    const int length = std::vsnprintf(nullptr, 0, fmt, copy);
    va_end(copy);
    std::string out;
    if (length > 0) {
        std::vector<char> buffer(static_cast<std::size_t>(length) + 1);
        std::vsnprintf(buffer.data(), buffer.size(), fmt, args);
        out.assign(buffer.data(), static_cast<std::size_t>(length));
    }
    va_end(args);
    return out;
}

std::string replaceEnv(std::string str)
{
    static const std::regex variable(R"(\$\{(\w+)\})");
    std::string out;
    std::smatch match;
    while (std::regex_search(str, match, variable)) {
        const char *value = std::getenv(match.str(1).c_str());
        out += match.prefix().str();
        out += value != nullptr ? value : "";
        str = match.suffix().str();
    }
    return out + str;
}
} // namespace coil
