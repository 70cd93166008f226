#pragma once
// The canvas's pointer tools, one picked at a time (the Tools menu and tool bar).

namespace vf::app {

enum class Tool { Select, Drop, Spatter, Comb, CircularComb, Swirl, Stylus, Text, Pan };

} // namespace vf::app
