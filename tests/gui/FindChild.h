#pragma once
// The GUI tests find the real widgets by object name; a missing one is a broken test, not a
// failed check, so it stops the test at once with the name it looked for.
#include <QWidget>

namespace vf::test {

template <typename T>
T* child(const QObject& parent, const char* name)
{
    T* widget = parent.findChild<T*>(QLatin1String(name));
    if (!widget)
        qFatal("no %s named %s", T::staticMetaObject.className(), name);
    return widget;
}

} // namespace vf::test
