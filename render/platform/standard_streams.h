#pragma once
// Standard input, output and error as the process found them: a closed one is opened on the
// null device before anything else opens a file, so that nothing takes its number. Linux tells
// and reopens them; the portable layer can do neither (portable/standard_streams.cpp).

namespace lb::platform {

// The standard streams (0, 1, 2) that were closed when the process started, as bits (1 << fd),
// each now open on the null device, so that no file, pipe or socket opened later takes its
// number: with descriptor 1 closed, the X server's socket became stdout and a report written
// there went into the X connection (the batch hung). Call first in main. The portable layer
// can neither tell nor reopen a closed descriptor and returns 0.
unsigned reopenClosedStandardStreams();
// Whether reopenClosedStandardStreams() can (false in the portable layer): the tests of a closed
// stdout skip where it cannot.
bool canReopenStandardStreams();

} // namespace lb::platform
