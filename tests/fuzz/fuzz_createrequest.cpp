// SPDX-License-Identifier: MIT
// The argument of RTM::Manager::create_component (`ConsoleIn?instance_name=c&exec_cxt…`,
// `RTC:vendor:category:impl:language:version?…`) and the manager address it may name.
// A request that parses is forwarded to a slave as toStringWithoutManager(), which must parse
// to the same request.

#include "createrequest.h"

#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const std::string text(reinterpret_cast<const char *>(data), size);
    std::string error;
    const std::optional<Runtime::CreateRequest> request = Runtime::CreateRequest::parse(text, &error);
    if (!request)
        return 0;
    if (request->managerAddress) {
        std::string host;
        int port = 0;
        Runtime::parseHostPort(*request->managerAddress, &host, &port, &error);
    }
    const std::optional<Runtime::CreateRequest> forwarded =
        Runtime::CreateRequest::parse(request->toStringWithoutManager(), &error);
    if (!forwarded || forwarded->implementationId != request->implementationId
        || forwarded->vendor != request->vendor || forwarded->category != request->category
        || forwarded->language != request->language || forwarded->version != request->version
        || forwarded->properties.entries() != request->properties.entries())
        std::abort();
    return 0;
}
