#pragma once
// `vectorfluid render` arguments, parsed and checked before any simulation starts.
#include "render/Exporter.h"

#include <QCommandLineParser>
#include <QString>
#include <QStringList>

#include <optional>

namespace vf::app {

struct RenderOptions {
    QString scene;
    std::optional<qint64> steps;
    std::optional<double> dt;
    QString backend;                // "reference", "opencl", or empty: OpenCL when a device exists
    std::optional<int> device;      // --device N, an index into `vectorfluid devices`
    QStringList outputs;
    render::ExportOptions exportOptions;
    QString framesDir;
    qint64 every = 0;
    QString statsFile;
    qint64 checkTopologyEvery = 0;  // --check-topology K: an exact crossing check every K steps; 0: none
};

// A command-line value read into `into`: an empty string, or one line naming the option, the value
// and the range it must be in. Shared by the commands.
QString wholeNumber(const QString& option, const QString& value, qint64 minimum, qint64 maximum, qint64& into);
QString positiveNumber(const QString& option, const QString& value, double maximum, double& into);

// The synopsis of `vectorfluid render` (docs/command-line.md).
extern const char* const renderUsage;

// Declares render's options and its SCENE argument to `parser`.
void addRenderOptions(QCommandLineParser& parser);

// The options from a parser that has parsed render's arguments. On failure returns nullopt and
// sets `error` to one line. With nothing asked to be written (no --out, --stats or --frames), the
// output is SCENE's name with .svg, beside it.
std::optional<RenderOptions> renderOptions(const QCommandLineParser& parser, QString& error);

} // namespace vf::app
