// A .vfscene file (model/SceneReader.cpp). A scene it accepts must also survive being written and
// read back, the path every save takes.
#include "FuzzInput.h"

#include "model/SceneFile.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const vf::model::SceneReadResult read = vf::model::parseScene(fuzzInput(data, size), QStringLiteral("fuzz.vfscene"));
    if (read.ok() && !vf::model::parseScene(vf::model::sceneToJson(read.scene), QStringLiteral("again.vfscene")).ok())
        std::abort();
    return 0;
}
