#include "render/BufferedWriter.h"

#include "model/AtomicFile.h"

#include <charconv>

namespace vf::render {
namespace {
constexpr std::size_t kChunkSize = 1 << 16;
}

BufferedWriter::BufferedWriter(QIODevice& device) : m_device(device)
{
    m_buffer.reserve(kChunkSize + 64);
}

BufferedWriter& BufferedWriter::operator<<(std::string_view text)
{
    m_buffer.append(text);
    flushIfFull();
    return *this;
}

BufferedWriter& BufferedWriter::operator<<(const QString& text)
{
    const QByteArray utf8 = text.toUtf8();
    return *this << utf8;
}

BufferedWriter& BufferedWriter::operator<<(const QByteArray& bytes)
{
    return *this << std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size()));
}

BufferedWriter& BufferedWriter::operator<<(char c)
{
    m_buffer.push_back(c);
    flushIfFull();
    return *this;
}

BufferedWriter& BufferedWriter::operator<<(double value)
{
    char text[32]; // the longest shortest-round-trip double is 24 characters
    const std::to_chars_result result = std::to_chars(text, text + sizeof text, value);
    m_buffer.append(text, result.ptr);
    flushIfFull();
    return *this;
}

QString BufferedWriter::finish()
{
    flush();
    return m_error;
}

void BufferedWriter::flushIfFull()
{
    if (m_buffer.size() >= kChunkSize)
        flush();
}

void BufferedWriter::flush()
{
    m_size += m_buffer.size();
    if (m_error.isEmpty() && !m_buffer.empty())
        m_error = model::writeAll(m_device, m_buffer.data(), static_cast<qint64>(m_buffer.size()));
    m_buffer.clear();
}

} // namespace vf::render
