#pragma once
// Tests of what the platform layer may not do (render/platform/process_bounds.h): skipped,
// with the reason, in the portable layer's build (`scripts/test --portable`).

#include "process_bounds.h"
#include "standard_streams.h"

#include <QTest>

#define LB_SKIP_WITHOUT_MEMORY_BOUNDS()                                                            \
    do {                                                                                           \
        if (!lb::platform::canBoundMemory())                                                       \
            QSKIP("this build's platform layer cannot bound a process's memory");                  \
    } while (false)

// A closed stdout can be told and reopened on /dev/null (render/platform/stream_output.h).
#define LB_SKIP_WITHOUT_STANDARD_STREAMS()                                                         \
    do {                                                                                           \
        if (!lb::platform::canReopenStandardStreams())                                             \
            QSKIP("this build's platform layer cannot tell a closed standard output");             \
    } while (false)
