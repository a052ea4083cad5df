// SPDX-License-Identifier: MIT
#pragma once

#include <functional>
#include <string>
#include <vector>

/// OpenRTM-aist's own Throughput example, run from an installed prefix beside the SDK's benchmark.
namespace OpenRtmThroughput {

/// One data size as the example's result file reports it (its latencies are one-way, receive
/// time minus the sender's time stamp; its throughput is the payload over the mean latency).
struct Row
{
    unsigned long elements = 0;
    double minUs = 0;
    double maxUs = 0;
    double meanUs = 0;
    double stddevUs = 0;
    double mibPerSecond = 0;
};

/// What one run gave: the rows, or why there are none.
struct Run
{
    std::vector<Row> rows;
    std::string error;
};

/// The example's program under @p prefix, or an empty string when it is not installed.
std::string programIn(const std::string &prefix);

/**
 * Runs the example with two components in one process (RTC::TimedDoubleSeq, push, flush,
 * corba_cdr; 1 to @p maxElements elements, doubling, 100 samples per size) in a temporary folder,
 * without name service. Kills it after @p timeoutSeconds.
 */
Run runSameProcess(const std::string &prefix, unsigned long maxElements, int timeoutSeconds);

/// Loopback ports of one two-process run: each example's manager listens on its own, and
/// `noMaster` is one where nothing listens (each looks for a master manager there and stays alone).
struct Ports
{
    unsigned sender = 0;
    unsigned receiver = 0;
    unsigned noMaster = 0;
};

/**
 * Connects the sender's `out` to the receiver's `in` (push, flush, corba_cdr) and activates the
 * sender; each example's manager is at `corbaloc:iiop:127.0.0.1:<port>/manager`. Returns what went
 * wrong, or an empty string.
 */
using Connect = std::function<std::string(const Ports &)>;

/**
 * Runs the example in two processes (sender and receiver, one Throughput0 each, the same sizes
 * and samples as runSameProcess) and reads the receiver's results. @p connect joins them once
 * both have started. Both are killed after @p timeoutSeconds.
 */
Run runTwoProcesses(const std::string &prefix, unsigned long maxElements, int timeoutSeconds,
                    const Ports &ports, const Connect &connect);

/// The rows of a result file (`size min max mean stddev Mbps`, seconds; `#` comments).
std::vector<Row> parseResults(const std::string &text);

} // namespace OpenRtmThroughput
