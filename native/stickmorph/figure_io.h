// Forwarding header: figure_io moved out of the engine into the IO library
// (target stickmorph_io, native/io/). The old include path keeps working
// while code that includes it is rewritten on other branches; new code
// includes "stickmorph/io/figure_io.h" and links stickmorph_io.
#pragma once

#include "stickmorph/io/figure_io.h"
