#pragma once
// Cairo gives an EPS the bounding box of its ink. A designer placing the file in a layout (or
// lining up a series of frames) needs the page instead, also when the background is off, so this
// filter rewrites the DSC bounding-box comments on their way to the file; the rest passes through.
#include <QByteArray>
#include <QIODevice>
#include <QString>

#include <cairo.h>

namespace vf::render {

class EpsBoundingBoxFilter {
public:
    // The box is 0 0 width height in whole points.
    EpsBoundingBoxFilter(QIODevice& out, int width, int height);

    // A cairo_write_func_t; `closure` is the filter.
    static cairo_status_t write(void* closure, const unsigned char* data, unsigned int length);

    // Passes on an unterminated last line, if any; returns an empty string or what went wrong,
    // including a document that does not end with its %%EOF trailer.
    [[nodiscard]] QString finish();
    // What went wrong writing so far, or an empty string.
    const QString& error() const { return m_error; }

private:
    bool filter(const char* data, qint64 length);
    bool forwardLine();
    bool forward(const char* data, qint64 length);

    QIODevice& m_out;
    QByteArray m_box;
    QByteArray m_line;      // the header line being collected
    bool m_inHeader = true; // until %%EndPageSetup, after which nothing needs rewriting
    QString m_error;
    static constexpr qint64 tailLength = 16;
    QByteArray m_tail;  // the last bytes written: a complete document ends with %%EOF
};

} // namespace vf::render
