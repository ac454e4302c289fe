// Forwarding header: json moved out of the engine into the IO library
// (target stickmorph_io, native/io/). The old include path keeps working
// while code that includes it is rewritten on other branches; new code
// includes "stickmorph/io/json.h" and links stickmorph_io.
#pragma once

#include "stickmorph/io/json.h"
