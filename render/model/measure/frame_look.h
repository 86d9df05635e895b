#pragma once
// Whether a frame the user's program drew shows anything: every pixel the background (the
// object is off screen or its matrices collapse it), or the object all black (its light or
// colour inputs are fed nothing). Said once a program starts to draw, so that a pasted
// shader that draws nothing is not a silent black.

#include <QString>

#include <cstddef>
#include <cstdint>

namespace lb {

enum class FrameLook { Drawn, AllBackground, AllBlack };

// `rgba`: `count` pixels, 4 bytes each (glReadPixels' RGBA, UNSIGNED_BYTE), of a view cleared
// to the background (compare.h) before the objects were drawn, no overlay yet.
FrameLook frameLook(const std::uint8_t *rgba, std::size_t count);

// The sentence the window and the command line give for a look other than Drawn; empty for
// Drawn.
QString frameLookWarning(FrameLook look);

} // namespace lb
