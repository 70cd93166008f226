// An SVG file for Import SVG (model/SvgImport.cpp, SvgPathData.cpp, SvgSyntax.cpp), on the unit
// canvas at the default tracking spacing (sim::TrackingSettings::maxSpacing).
#include "FuzzInput.h"

#include "model/SvgImport.h"
#include "sim/Tracking.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    vf::model::importSvg(fuzzInput(data, size), QStringLiteral("fuzz.svg"), 1.0, 1.0, vf::sim::TrackingSettings{}.maxSpacing);
    return 0;
}
