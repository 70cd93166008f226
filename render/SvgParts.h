#pragma once
// The parts of an SVG file that the still SVG writer and the animated one share.
#include "render/BufferedWriter.h"
#include "render/Page.h"
#include "render/PathEmitter.h"
#include "render/XmlNames.h"

#include <QColor>

namespace vf::render {

// Absolute coordinates (relative ones would accumulate rounding), a command letter only where it
// changes, shortest round-trip numbers: exact for the doubles given, or, with a `step` (a power
// of ten, render/SvgRounding.h), rounded to it and as short as that allows.
class SvgPathData final : public PathSink {
public:
    explicit SvgPathData(BufferedWriter& out, double step = 0) : m_out(out), m_step(step) {}

    void moveTo(sim::Vec2 point) override;
    void lineTo(sim::Vec2 point) override;
    void cubicTo(sim::Vec2 control1, sim::Vec2 control2, sim::Vec2 end) override;
    void closePath() override;

private:
    void command(char letter);
    void write(sim::Vec2 point);

    BufferedWriter& m_out;
    double m_step;
    char m_last = 0;
};

// ` fill="#rrggbb"`, and ` fill-opacity="a"` for a translucent colour.
void writeSvgFill(BufferedWriter& xml, const QColor& color);

// The XML declaration and the <svg> start tag: the page's size in points, the canvas as viewBox.
void writeSvgHeader(BufferedWriter& xml, const model::Drawing& drawing, const Page& page);

// The background: its own locked Inkscape layer, so a designer editing the regions cannot grab it
// by accident.
void writeSvgBackground(BufferedWriter& xml, const model::Drawing& drawing, UniqueXmlIds& ids);

} // namespace vf::render
