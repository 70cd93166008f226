// A .vfproj file (model/ProjectReader.cpp): the JSON manifest and the compressed state blobs.
#include "FuzzInput.h"

#include "model/ProjectFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    vf::model::parseProject(fuzzInput(data, size), QStringLiteral("fuzz.vfproj"));
    return 0;
}
