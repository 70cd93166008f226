#pragma once
// What the JSON file formats (scene and project files) share: strict reading, where every value
// carries its key path and every failed check throws a ReadError naming it, objects read through a
// table of their keys so that an unknown key is an error; and colours as text.
#include <QByteArray>
#include <QColor>
#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QStringList>

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <utility>
#include <vector>

namespace vf::model::json {

// Thrown by any check; the file's reader turns it into the error line. `where` is a key path or
// line:col.
struct ReadError {
    QString where;
    QString what;
};

// "regions[1].shape.circle.radius": where a value sits in the file, as the error line names it.
// A default-constructed path is the top level.
class KeyPath {
public:
    KeyPath() = default;
    KeyPath key(const QString& name) const { return KeyPath(m_text.isEmpty() ? name : m_text + u'.' + name); }
    KeyPath index(qsizetype i) const { return KeyPath(m_text + u'[' + QString::number(i) + u']'); }
    [[noreturn]] void fail(const QString& what) const { throw ReadError{m_text, what}; }

private:
    explicit KeyPath(QString text) : m_text(std::move(text)) {}
    QString m_text;
};

// Quotes text from the file for a message, short enough to keep the message one readable line.
QString quoted(const QString& text);
QString describe(const QJsonValue& value);

// A JSON value with its key path: every check can say where it failed. Absent keys are
// Undefined values, so optional and required keys are read the same way.
class Field {
public:
    Field(QJsonValue value, KeyPath path) : m_value(std::move(value)), m_path(std::move(path)) {}

    bool exists() const { return !m_value.isUndefined(); }
    bool isNull() const { return m_value.isNull(); }
    bool isObject() const { return m_value.isObject(); }
    const KeyPath& path() const { return m_path; }
    [[noreturn]] void fail(const QString& what) const { m_path.fail(what); }

    Field member(const QString& key) const { return {object().value(key), m_path.key(key)}; }
    Field element(const QJsonArray& array, qsizetype i) const { return {array.at(i), m_path.index(i)}; }

    QJsonObject object() const;
    QJsonArray array(qsizetype minSize, qsizetype maxSize) const;
    QString string() const;
    QString name() const;  // a string that is not empty or blank
    bool boolean() const;
    double number() const;
    double number(double min, double max) const;
    double nonNegative() const;
    double positive(double max) const;
    std::int64_t integer(std::int64_t min, std::int64_t max) const;
    template <typename T>
    T choice(std::initializer_list<std::pair<QString, T>> choices) const
    {
        const QString text = string();
        QStringList names;
        for (const auto& [name, value] : choices) {
            if (name == text)
                return value;
            names << u'"' + name + u'"';
        }
        fail(QStringLiteral("must be one of %1, not %2").arg(names.join(QStringLiteral(", ")), quoted(text)));
    }

private:
    void expectType(QJsonValue::Type type, const QString& wanted) const;

    QJsonValue m_value;
    KeyPath m_path;
};

// Only #rrggbb and #rrggbbaa: QColor's own parser also takes names and #aarrggbb, which would make
// "#rrggbbaa" from CSS or SVG silently mean something else.
QColor color(const Field& field);
// The text color() reads back: "#rrggbb", or "#rrggbbaa" when not opaque.
QString colorText(const QColor& color);

// ---- objects: a table per object says which keys exist, which are required, how each is read --

template <typename Target>
struct Key {
    QString name;
    bool required;
    void (*read)(const Field&, Target&);
};

template <typename Target>
bool hasKey(std::span<const Key<Target>> keys, const QString& name)
{
    return std::any_of(keys.begin(), keys.end(), [&name](const Key<Target>& key) { return key.name == name; });
}

template <typename Target>
QString keyList(std::span<const Key<Target>> keys)
{
    QStringList names;
    for (const Key<Target>& key : keys)
        names << key.name;
    return names.join(QStringLiteral(", "));
}

// Keys are read in table order, absent optional keys keep the target's defaults.
template <typename Target>
void readObject(const Field& field, Target& target, std::span<const Key<Target>> keys)
{
    const QJsonObject object = field.object();
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (!hasKey(keys, it.key()))
            field.member(it.key()).fail(QStringLiteral("unknown key (expected one of: %1)").arg(keyList(keys)));
    }
    for (const Key<Target>& key : keys) {
        const Field child = field.member(key.name);
        if (child.exists())
            key.read(child, target);
        else if (key.required)
            child.fail(QStringLiteral("missing (required)"));
    }
}

// For a key that was read before its table was chosen ("tool" picks the stroke's table).
template <typename Target>
void readAlready(const Field&, Target&) {}

template <typename T, std::size_t N>
T readAs(const Field& field, const Key<T> (&keys)[N])
{
    T value;
    readObject(field, value, std::span<const Key<T>>(keys));
    return value;
}

template <typename T, typename ReadItem>
std::vector<T> readList(const Field& field, qsizetype minSize, qsizetype maxSize, ReadItem readItem)
{
    const QJsonArray array = field.array(minSize, maxSize);
    std::vector<T> items;
    items.reserve(static_cast<std::size_t>(array.size()));
    for (qsizetype i = 0; i < array.size(); ++i)
        items.push_back(readItem(field.element(array, i)));
    return items;
}

// ---- bytes to JSON ----------------------------------------------------------------------------

// "line:col" of a byte offset, both 1-based, the column counted in characters.
QString location(const QByteArray& json, qsizetype offset);

// Messages may quote the file's own text (keys, expressions): keep the result on one line.
QString oneLine(QString text);

} // namespace vf::model::json
