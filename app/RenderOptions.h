#pragma once
// `vectorfluid render` arguments, parsed and checked before any simulation starts.
#include "render/Exporter.h"

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

// Parses the arguments after `render`. On failure returns nullopt and sets `error` to one line.
std::optional<RenderOptions> parseRenderOptions(const QStringList& arguments, QString& error);

} // namespace vf::app
