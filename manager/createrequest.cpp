// SPDX-License-Identifier: MIT
#include "createrequest.h"

#include <cctype>

namespace Runtime {

namespace {

bool parseId(const std::string &id, CreateRequest *request, std::string *error)
{
    if (id.compare(0, 4, "RTC:") != 0) {
        request->implementationId = id;
        return true;
    }
    // RTC:vendor:category:impl_id:language:version (language may be left out, as OpenRTM allows).
    const std::vector<std::string> parts = split(id, ':', false);
    if ((parts.size() != 5 && parts.size() != 6) || parts[3].empty()) {
        *error = "malformed component id '" + id + "' (expected RTC:vendor:category:type:language:version)";
        return false;
    }
    request->vendor = parts[1];
    request->category = parts[2];
    request->implementationId = parts[3];
    request->language = parts.size() == 6 ? parts[4] : std::string();
    request->version = parts.back();
    return true;
}

bool applyParameter(const std::string &pair, CreateRequest *request, std::string *error)
{
    const size_t eq = pair.find('=');
    const std::string key = trimmed(pair.substr(0, eq));
    if (eq == std::string::npos || key.empty()) {
        *error = "malformed parameter '" + pair + "' (expected key=value)";
        return false;
    }
    const std::string value = trimmed(pair.substr(eq + 1));
    if (key == "manager_address")
        request->managerAddress = value;
    else if (key == "manager_name")
        request->managerName = value;
    else if (key == "version")
        request->packageVersion = value;
    else
        request->properties.set(key, value);
    return true;
}

} // namespace

std::optional<CreateRequest> CreateRequest::parse(const std::string &text, std::string *error)
{
    const std::string input = trimmed(text);
    const size_t question = input.find('?');
    if (question != std::string::npos && input.find('?', question + 1) != std::string::npos) {
        *error = "more than one '?' in '" + input + "'";
        return std::nullopt;
    }
    CreateRequest request;
    const std::string id = trimmed(input.substr(0, question));
    if (id.empty()) {
        *error = "no component type in '" + input + "'";
        return std::nullopt;
    }
    if (!parseId(id, &request, error))
        return std::nullopt;
    if (question != std::string::npos) {
        for (const std::string &pair : split(input.substr(question + 1), '&')) {
            if (!applyParameter(pair, &request, error))
                return std::nullopt;
        }
    }
    if (request.managerAddress && request.managerName) {
        *error = "both manager_address and manager_name given";
        return std::nullopt;
    }
    return request;
}

std::string CreateRequest::toStringWithoutManager() const
{
    std::string text = implementationId;
    if (!vendor.empty() || !category.empty() || !language.empty() || !version.empty())
        text = "RTC:" + vendor + ':' + category + ':' + implementationId + ':'
               + (language.empty() ? std::string() : language + ':') + version;
    char separator = '?';
    if (!packageVersion.empty()) {
        text += "?version=" + packageVersion;
        separator = '&';
    }
    for (const auto &[key, value] : properties.entries()) {
        text += separator + key + '=' + value;
        separator = '&';
    }
    return text;
}

bool parseHostPort(const std::string &text, std::string *host, int *port, std::string *error)
{
    const size_t colon = text.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == text.size()) {
        *error = "malformed manager address '" + text + "' (expected host:port)";
        return false;
    }
    const std::string portText = text.substr(colon + 1);
    for (char c : portText) {
        if (!std::isdigit(static_cast<unsigned char>(c))) {
            *error = "malformed port in manager address '" + text + "'";
            return false;
        }
    }
    const long value = portText.size() > 5 ? 0 : std::stol(portText);
    if (value < 1 || value > 65535) {
        *error = "port out of range in manager address '" + text + "'";
        return false;
    }
    *host = text.substr(0, colon);
    *port = int(value);
    return true;
}

} // namespace Runtime
