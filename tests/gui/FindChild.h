#pragma once
// The GUI tests find the real widgets by object name; a missing one is a broken test, not a
// failed check, so it stops the test at once with the name it looked for. Dialogs a click opens
// are answered by whenModal.
#include <QApplication>
#include <QTimer>
#include <QWidget>

#include <functional>

namespace vf::test {

template <typename T>
T* child(const QObject& parent, const char* name)
{
    T* widget = parent.findChild<T*>(QLatin1String(name));
    if (!widget)
        qFatal("no %s named %s", T::staticMetaObject.className(), name);
    return widget;
}

// Runs `act` on the modal dialog of type T once one is open (the action that opens it blocks in
// its own event loop until `act` closes it).
template <typename T>
void whenModal(std::function<void(T*)> act)
{
    QTimer::singleShot(10, qApp, [act] {
        if (auto* dialog = qobject_cast<T*>(QApplication::activeModalWidget()))
            act(dialog);
        else
            whenModal<T>(act);
    });
}

} // namespace vf::test
