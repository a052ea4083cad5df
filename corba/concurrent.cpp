// SPDX-License-Identifier: MIT
#include "concurrent.h"

#include "orb.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace Corba {

void forEachConcurrently(std::size_t count, const std::function<void(std::size_t)> &task,
                         std::size_t maxThreads)
{
    std::atomic<std::size_t> next {0};
    std::mutex mutex;
    std::exception_ptr failure;
    const int timeout = Orb::callTimeout();
    const auto work = [&] {
        const ThreadCallTimeout sameTimeout(timeout);
        for (std::size_t i = next++; i < count; i = next++) {
            try {
                task(i);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(mutex);
                if (!failure)
                    failure = std::current_exception();
            }
        }
    };
    std::vector<std::thread> helpers;
    const std::size_t threads = std::min(count, std::max<std::size_t>(maxThreads, 1));
    for (std::size_t i = 1; i < threads; ++i)
        helpers.emplace_back(work);
    work();
    for (std::thread &helper : helpers)
        helper.join();
    if (failure)
        std::rethrow_exception(failure);
}

} // namespace Corba
