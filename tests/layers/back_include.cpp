// Compiled by the test `layers_refuse_a_back_include` (CMakeLists.txt) with the
// include path of the develop layer: it must fail, because physics is above develop.
#include "physics/world.h"
