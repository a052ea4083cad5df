// SPDX-License-Identifier: MIT
#pragma once

#include "properties.h"

#include <chrono>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <vector>

namespace Runtime {

/// Marshalled data as it travels between ports.
using CdrBytes = std::vector<unsigned char>;

/// Marshalled bytes owned by someone else (valid until that owner changes them).
struct CdrView
{
    CdrView() = default;
    CdrView(const unsigned char *bytes, size_t length) : data(bytes), size(length) {}

    const unsigned char *data = nullptr;
    size_t size = 0;

    CdrBytes bytes() const { return CdrBytes(data, data + size); }
    static CdrView of(const CdrBytes &bytes) { return {bytes.data(), bytes.size()}; }
};

/**
 * One marshalled sample as a buffer keeps it: bytes it owns, either a vector moved in or a
 * buffer taken over from the ORB as it arrived (so a received sample is never copied to be kept).
 */
class CdrSample
{
public:
    using Release = void (*)(unsigned char *);

    explicit CdrSample(CdrBytes bytes)
        : m_vector(std::move(bytes))
        , m_view(CdrView::of(m_vector))
    {
    }
    /// Takes over @p bytes, which @p release frees.
    CdrSample(unsigned char *bytes, size_t size, Release release)
        : m_view(bytes, size)
        , m_adopted(bytes)
        , m_release(release)
    {
    }
    ~CdrSample()
    {
        if (m_release != nullptr)
            m_release(m_adopted);
    }
    CdrSample(const CdrSample &) = delete;
    CdrSample &operator=(const CdrSample &) = delete;

    const CdrView &view() const { return m_view; }
    const unsigned char *data() const { return m_view.data; }
    size_t size() const { return m_view.size; }

private:
    CdrBytes m_vector;
    CdrView m_view;
    unsigned char *m_adopted = nullptr;
    Release m_release = nullptr;
};

/// One marshalled sample shared between a buffer and its readers (no copy for each reader).
using SharedCdr = std::shared_ptr<const CdrSample>;

/**
 * A bounded buffer of marshalled samples with OpenRTM's policies, configured from connector
 * properties below `buffer.` (`length`, `write.full_policy` overwrite|do_nothing|block,
 * `write.timeout`, `read.empty_policy` readback|do_nothing|block, `read.timeout`; timeouts in seconds).
 * Thread-safe.
 */
class RingBuffer
{
public:
    enum class Status { Ok, Full, Empty, Timeout };

    explicit RingBuffer(const Properties &bufferProperties = {});

    /// Stores @p data according to the write policy (moved in: pass an rvalue to avoid a copy).
    Status write(CdrBytes data);
    /// The same for a sample made elsewhere (shared, not copied).
    Status write(SharedCdr data);
    /// Takes the oldest sample according to the read policy ("readback" repeats the last one).
    Status read(SharedCdr *data);
    /// The same, copied out.
    Status read(CdrBytes *data);
    /// Unread samples.
    size_t readable() const;
    size_t length() const { return m_length; }
    /// Wakes blocked readers/writers; they return Timeout.
    void close();

private:
    enum class FullPolicy { Overwrite, DoNothing, Block };
    enum class EmptyPolicy { Readback, DoNothing, Block };

    mutable std::mutex m_mutex;
    std::condition_variable m_changed;
    std::deque<SharedCdr> m_samples;
    SharedCdr m_last; ///< what readback repeats; shared with the reader that took it
    bool m_closed = false;
    size_t m_length = 8;
    FullPolicy m_fullPolicy = FullPolicy::Overwrite;
    EmptyPolicy m_emptyPolicy = EmptyPolicy::Readback;
    std::chrono::milliseconds m_writeTimeout{1000};
    std::chrono::milliseconds m_readTimeout{1000};
};

} // namespace Runtime
