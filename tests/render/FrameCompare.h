#pragma once
// Pictures compared pixel by pixel: our own PNG render of a drawing (render/PngWriter) against what
// another program made of an exported file.
#include "render/Writers.h"

#include <QBuffer>
#include <QImage>
#include <QtTest>

#include <cstdlib>

namespace vf::test {

// `drawing` as render::writePng paints it, in ARGB32.
inline QImage ourRender(const model::Drawing& drawing, const render::ExportOptions& options)
{
    QBuffer png;
    png.open(QIODevice::WriteOnly);
    if (const QString error = render::writePng(drawing, options, png); !error.isEmpty())
        qFatal("%s", qPrintable(error));
    return QImage::fromData(png.data(), "png").convertToFormat(QImage::Format_ARGB32);
}

// The share of pixels whose four channels all differ by at most `tolerance` (antialiasing differs
// between renderers); 0 for images of different sizes.
inline double agreement(const QImage& a, const QImage& b, int tolerance = 24)
{
    if (a.size() != b.size() || a.isNull())
        return 0;
    const QImage p = a.convertToFormat(QImage::Format_ARGB32), q = b.convertToFormat(QImage::Format_ARGB32);
    qint64 same = 0;
    for (int y = 0; y < p.height(); ++y) {
        for (int x = 0; x < p.width(); ++x) {
            const QRgb s = p.pixel(x, y), t = q.pixel(x, y);
            same += std::abs(qRed(s) - qRed(t)) <= tolerance && std::abs(qGreen(s) - qGreen(t)) <= tolerance
                    && std::abs(qBlue(s) - qBlue(t)) <= tolerance && std::abs(qAlpha(s) - qAlpha(t)) <= tolerance;
        }
    }
    return double(same) / double(p.width() * p.height());
}

} // namespace vf::test
