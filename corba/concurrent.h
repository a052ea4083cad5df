// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <functional>

namespace Corba {

/// How many remote calls that do not depend on each other run at once by default.
constexpr std::size_t defaultConcurrency = 8;

/**
 * Runs `task(0)` … `task(count - 1)` on up to `maxThreads` threads at once (the calling thread is
 * one of them) and returns when all have ended. Each thread makes its remote calls with the
 * caller's call timeout (Orb::callTimeout()), so a hung peer costs one timeout, not one per call.
 * The first exception a task throws is rethrown here once every task has ended.
 */
void forEachConcurrently(std::size_t count, const std::function<void(std::size_t)> &task,
                         std::size_t maxThreads = defaultConcurrency);

} // namespace Corba
