// SPDX-License-Identifier: MIT
// Allocation as in a release build of a server whose memory is limited, for a harness under
// AddressSanitizer: a request the allocator cannot satisfy throws std::bad_alloc instead of ending
// the process.
//
// omniORB sizes some buffers from lengths a peer sends: a TypeCode's encapsulation length asks for
// up to 2 GiB, or, read as a negative int, about 16 EiB. Built normally, the large request is only
// reserved (never touched) and freed again, the impossible one throws std::bad_alloc; omniORB
// answers with an exception and the server goes on serving (fuzz_giop_replay shows it with
// tests/data/fuzz/fuzz_giop/typecode-negative-length). Under ASan the first costs seconds (ASan
// marks the whole block) and the second is reported as a crash whatever its options say. So
// fuzz_giop replaces the allocation functions with ones over malloc (still checked by ASan, which
// gives nullptr for the impossible size with allocator_may_return_null=1) that refuse a single
// block over 256 MiB as a server limited with `ulimit -v` would: what is found is then what a
// running manager would do. Only ASan's check that new[] is not freed with delete (and the like)
// is lost for this harness.
#include <algorithm>
#include <cstdlib>
#include <new>

extern "C" const char *__asan_default_options()
{
    return "allocator_may_return_null=1";
}

namespace {

constexpr std::size_t LargestBlock = std::size_t(256) << 20;

void *tryAllocate(std::size_t size)
{
    return size > LargestBlock ? nullptr : std::malloc(size == 0 ? 1 : size);
}

void *allocate(std::size_t size)
{
    if (void *memory = tryAllocate(size))
        return memory;
    throw std::bad_alloc();
}

void *allocateAligned(std::size_t size, std::align_val_t alignment)
{
    void *memory = nullptr;
    const std::size_t boundary = std::max(sizeof(void *), static_cast<std::size_t>(alignment));
    if (size > LargestBlock || posix_memalign(&memory, boundary, size == 0 ? 1 : size) != 0)
        throw std::bad_alloc();
    return memory;
}

} // namespace

void *operator new(std::size_t size) { return allocate(size); }
void *operator new[](std::size_t size) { return allocate(size); }
void *operator new(std::size_t size, const std::nothrow_t &) noexcept { return tryAllocate(size); }
void *operator new[](std::size_t size, const std::nothrow_t &) noexcept { return tryAllocate(size); }
void *operator new(std::size_t size, std::align_val_t alignment) { return allocateAligned(size, alignment); }
void *operator new[](std::size_t size, std::align_val_t alignment) { return allocateAligned(size, alignment); }
void *operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t &) noexcept
{
    try {
        return allocateAligned(size, alignment);
    } catch (const std::bad_alloc &) {
        return nullptr;
    }
}
void *operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t &tag) noexcept
{
    return operator new(size, alignment, tag);
}

void operator delete(void *memory) noexcept { std::free(memory); }
void operator delete[](void *memory) noexcept { std::free(memory); }
void operator delete(void *memory, const std::nothrow_t &) noexcept { std::free(memory); }
void operator delete[](void *memory, const std::nothrow_t &) noexcept { std::free(memory); }
void operator delete(void *memory, std::size_t) noexcept { std::free(memory); }
void operator delete[](void *memory, std::size_t) noexcept { std::free(memory); }
void operator delete(void *memory, std::align_val_t) noexcept { std::free(memory); }
void operator delete[](void *memory, std::align_val_t) noexcept { std::free(memory); }
void operator delete(void *memory, std::size_t, std::align_val_t) noexcept { std::free(memory); }
void operator delete[](void *memory, std::size_t, std::align_val_t) noexcept { std::free(memory); }
void operator delete(void *memory, std::align_val_t, const std::nothrow_t &) noexcept { std::free(memory); }
void operator delete[](void *memory, std::align_val_t, const std::nothrow_t &) noexcept { std::free(memory); }
