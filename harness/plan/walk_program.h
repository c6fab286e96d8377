// The program walker moved to program/walk_program.h (the case checks use it
// too); this name stays for the modules that include it from here.
#pragma once

#include "program/walk_program.h"
