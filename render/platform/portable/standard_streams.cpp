#include "standard_streams.h"

namespace lb::platform {

bool canReopenStandardStreams()
{
    return false;
}

unsigned reopenClosedStandardStreams()
{
    return 0; // standard C++ cannot tell a closed descriptor
}

} // namespace lb::platform
