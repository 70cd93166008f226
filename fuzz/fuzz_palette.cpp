// A GIMP .gpl palette (model/Palette.cpp). A palette it accepts must also survive being written and
// read back unchanged, the path every save takes.
#include "FuzzInput.h"

#include "model/Palette.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const vf::model::PaletteReadResult read = vf::model::parseGpl(fuzzInput(data, size), QStringLiteral("fuzz.gpl"));
    if (!read.ok())
        return 0;
    const vf::model::PaletteReadResult again = vf::model::parseGpl(vf::model::gplBytes(read.palette), QStringLiteral("again.gpl"));
    if (!again.ok() || !(again.palette == read.palette))
        std::abort();
    return 0;
}
