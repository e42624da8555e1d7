// Everything a translated program includes, as one header: it is the first
// line of every generated file, so the interpreter can precompile it once.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <util/point.hpp>

#include "plugin.hpp"
#include "translated.hpp"
#include "vv.hpp"
