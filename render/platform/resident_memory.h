#pragma once
// The process's resident memory, as the kernel counts it (/proc/self/statm). 0 where it
// cannot be read.

namespace lb {

long residentKB();

} // namespace lb
