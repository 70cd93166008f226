#pragma once
// Where file dialogs start when the user has not chosen a folder yet.
#include <QString>

namespace vf::app {

// The platform's documents folder where it exists (it may not, on a fresh account), else the home
// folder.
QString documentsFolder();

} // namespace vf::app
