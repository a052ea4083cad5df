// SPDX-License-Identifier: MIT
// rtc.conf text and rtmanager's command line (`-o key:value`, `-p`, `-d` …).
//
// The input is read as rtc.conf; its lines are also taken as command-line arguments. `-f` is left
// out (the harness reads no files: a missing configuration file is ignored). The properties read
// are then used as a connector's, whose buffer settings (`dataport.buffer.length`,
// `…write.timeout` …) are numbers in text.

#include "managerconfig.h"
#include "outportconnector.h"
#include "ringbuffer.h"

#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const std::string text(reinterpret_cast<const char *>(data), size);
    std::vector<std::string> errors;
    const Runtime::Properties file = Runtime::Properties::parseConf(text, &errors);

    std::vector<std::string> arguments = {"rtmanager", "-f", "/nonexistent/rtc.conf", "-i"};
    for (const std::string &line : Runtime::split(text, '\n', false))
        arguments.push_back(line == "-f" ? std::string("-i") : line);
    std::vector<char *> argv;
    for (std::string &argument : arguments)
        argv.push_back(argument.data());
    Runtime::Properties config;
    std::string error;
    Runtime::parseManagerArguments(int(argv.size()), argv.data(), &config, &error);
    config.merge(file);

    Runtime::RingBuffer buffer(Runtime::bufferProperties(config, "inport"));
    config.subtree("exec_cxt");
    config.isYes("manager.is_master");
    return 0;
}
