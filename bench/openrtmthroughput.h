// SPDX-License-Identifier: MIT
#pragma once

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

/// The rows of a result file (`size min max mean stddev Mbps`, seconds; `#` comments).
std::vector<Row> parseResults(const std::string &text);

} // namespace OpenRtmThroughput
