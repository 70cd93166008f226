#pragma once
// Text output to a QIODevice in large chunks, so writers can stream millions of numbers without
// building the file (or a region's path data) in memory. A failed write is remembered, not thrown.
#include <QIODevice>
#include <QString>

#include <cstdint>
#include <string>
#include <string_view>

namespace vf::render {

class BufferedWriter {
public:
    explicit BufferedWriter(QIODevice& device);
    BufferedWriter(const BufferedWriter&) = delete;
    BufferedWriter& operator=(const BufferedWriter&) = delete;

    BufferedWriter& operator<<(std::string_view text);
    BufferedWriter& operator<<(const char* text) { return *this << std::string_view(text); }
    BufferedWriter& operator<<(const QString& text); // UTF-8
    BufferedWriter& operator<<(const QByteArray& bytes);
    BufferedWriter& operator<<(char c);
    // The shortest text that reads back as exactly the same double (std::to_chars).
    BufferedWriter& operator<<(double value);

    // Bytes given so far, written or buffered.
    std::uint64_t size() const { return m_size + m_buffer.size(); }

    // Writes what is buffered; returns an empty string or what went wrong.
    [[nodiscard]] QString finish();

private:
    void flushIfFull();
    void flush();

    QIODevice& m_device;
    std::string m_buffer;
    QString m_error;
    std::uint64_t m_size = 0;
};

} // namespace vf::render
