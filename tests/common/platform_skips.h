#pragma once
// Tests of what the platform layer may not do (render/platform/process_bounds.h): skipped,
// with the reason, in the portable layer's build (`scripts/test --portable`).

#include "process_bounds.h"

#include <QTest>

#define LB_SKIP_WITHOUT_MEMORY_BOUNDS()                                                            \
    do {                                                                                           \
        if (!lb::platform::canBoundMemory())                                                       \
            QSKIP("this build's platform layer cannot bound a process's memory");                  \
    } while (false)
