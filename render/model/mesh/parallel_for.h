#pragma once
// Splitting a loop over threads for the mesh code (normal generation), without letting an
// exception escape a thread.

#include <cstddef>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace lb {

// Runs work(begin, end, part) over `parts` slices of [0, n) on as many threads. What a slice
// throws (std::bad_alloc) is thrown here once all have ended: an exception leaving a
// std::thread would end the process, and a thread still running would outlive its arrays.
template <typename F> void parallelFor(std::size_t n, std::size_t parts, F &&work)
{
    if (parts <= 1) {
        work(std::size_t(0), n, std::size_t(0));
        return;
    }
    std::vector<std::exception_ptr> failed(parts);
    const auto slice = [&](std::size_t p) {
        try {
            work(n * p / parts, n * (p + 1) / parts, p);
        } catch (...) {
            failed[p] = std::current_exception();
        }
    };
    std::vector<std::thread> threads;
    threads.reserve(parts);
    for (std::size_t p = 1; p < parts; ++p) {
        try {
            threads.emplace_back(slice, p);
        } catch (const std::system_error &) { // no thread to be had: the slice runs here
            slice(p);
        }
    }
    slice(0);
    for (std::thread &t : threads)
        t.join();
    for (const std::exception_ptr &e : failed)
        if (e)
            std::rethrow_exception(e);
}

} // namespace lb
