#include "app/ClipboardExport.h"

#include "render/Writers.h"

#include <QBuffer>
#include <QClipboard>
#include <QGuiApplication>
#include <QMimeData>

namespace vf::app {

QString copyAsSvg(const model::Drawing& drawing)
{
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    if (const QString error = render::writeSvg(drawing, render::ExportOptions{}, buffer); !error.isEmpty())
        return QStringLiteral("cannot copy as SVG: %1").arg(error);
    auto* mime = new QMimeData;
    mime->setData(QStringLiteral("image/svg+xml"), buffer.data());
    mime->setText(QString::fromUtf8(buffer.data()));
    QGuiApplication::clipboard()->setMimeData(mime); // the clipboard owns it
    return {};
}

} // namespace vf::app
