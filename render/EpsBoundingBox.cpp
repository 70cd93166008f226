#include "render/EpsBoundingBox.h"

#include "model/AtomicFile.h"

#include <algorithm>

namespace vf::render {

EpsBoundingBoxFilter::EpsBoundingBoxFilter(QIODevice& out, int width, int height)
    : m_out(out), m_box(QByteArrayLiteral("0 0 ") + QByteArray::number(width) + ' ' + QByteArray::number(height))
{
}

cairo_status_t EpsBoundingBoxFilter::write(void* closure, const unsigned char* data, unsigned int length)
{
    auto* self = static_cast<EpsBoundingBoxFilter*>(closure);
    return self->filter(reinterpret_cast<const char*>(data), length) ? CAIRO_STATUS_SUCCESS
                                                                     : CAIRO_STATUS_WRITE_ERROR;
}

QString EpsBoundingBoxFilter::finish()
{
    if (!m_line.isEmpty())
        forward(m_line.constData(), m_line.size());
    m_line.clear();
    // Cairo spools the page to a temporary file of its own and reports no failure to write it
    // there: the document then stops short of its trailer, or never starts.
    if (m_error.isEmpty() && !m_tail.trimmed().endsWith("%%EOF"))
        m_error = QStringLiteral("cairo could not write its PostScript spool (a full disk or a file size limit?): "
                                 "the EPS is incomplete");
    return m_error;
}

bool EpsBoundingBoxFilter::filter(const char* data, qint64 length)
{
    qint64 i = 0;
    while (m_inHeader && i < length) {
        const char c = data[i++];
        m_line += c;
        if (c == '\n' && !forwardLine())
            return false;
    }
    return i == length || forward(data + i, length - i);
}

bool EpsBoundingBoxFilter::forwardLine()
{
    if (m_line.startsWith("%%BoundingBox:"))
        m_line = "%%BoundingBox: " + m_box + '\n';
    else if (m_line.startsWith("%%PageBoundingBox:"))
        m_line = "%%PageBoundingBox: " + m_box + '\n';
    else if (m_line.startsWith("%%EndPageSetup"))
        m_inHeader = false;
    const bool written = forward(m_line.constData(), m_line.size());
    m_line.clear();
    return written;
}

bool EpsBoundingBoxFilter::forward(const char* data, qint64 length)
{
    if (m_error.isEmpty())
        m_error = model::writeAll(m_out, data, length);
    m_tail = (m_tail + QByteArray(data + std::max<qint64>(0, length - tailLength), std::min<qint64>(length, tailLength)))
                 .right(tailLength);
    return m_error.isEmpty();
}

} // namespace vf::render
