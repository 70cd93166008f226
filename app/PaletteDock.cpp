#include "app/PaletteDock.h"

#include "app/Folders.h"

#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QListWidget>
#include <QPainter>
#include <QToolButton>
#include <QSettings>
#include <QVBoxLayout>

namespace vf::app {

std::vector<QColor> PaletteDock::inks() const
{
    std::vector<QColor> colours;
    for (const model::PaletteColour& c : shown().colours)
        colours.push_back(c.colour);
    return colours;
}

namespace {

const QString filesKey = QStringLiteral("palettes/files");
constexpr int swatchSize = 22;

QIcon swatch(const QColor& colour)
{
    QPixmap pixmap(swatchSize, swatchSize);
    pixmap.fill(colour);
    QPainter painter(&pixmap);
    painter.setPen(QColor(0, 0, 0, 80));
    painter.drawRect(0, 0, swatchSize - 1, swatchSize - 1);
    painter.end();
    QIcon icon(pixmap);
    icon.addPixmap(pixmap, QIcon::Selected);  // the ink's own colour, not tinted by the selection
    return icon;
}

} // namespace

PaletteDock::PaletteDock(QWidget* parent)
    : QDockWidget(tr("Palette"), parent)
    , m_palettes(model::builtInPalettes())
    , m_choice(new QComboBox)
    , m_swatches(new QListWidget)
{
    setObjectName(QStringLiteral("paletteDock"));
    m_choice->setObjectName(QStringLiteral("paletteChoice"));
    m_swatches->setObjectName(QStringLiteral("swatches"));
    m_swatches->setViewMode(QListView::IconMode);
    m_swatches->setIconSize(QSize(swatchSize, swatchSize));
    m_swatches->setGridSize(QSize(swatchSize + 6, swatchSize + 6));
    m_swatches->setResizeMode(QListView::Adjust);
    m_swatches->setMovement(QListView::Static);
    m_swatches->setUniformItemSizes(true);
    m_swatches->setSelectionMode(QAbstractItemView::SingleSelection);
    // The swatch of the current ink framed, plainly: icon mode otherwise marks it with a sliver.
    m_swatches->setStyleSheet(QStringLiteral("QListWidget::item:selected { border: 2px solid palette(highlight); }"));

    // Narrow: the dock sits beside the canvas, which should keep the room.
    m_choice->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_choice->setMinimumContentsLength(8);
    auto* loadButton = new QToolButton;
    auto* saveButton = new QToolButton;
    auto* addButton = new QToolButton;
    loadButton->setText(tr("Load…"));
    saveButton->setText(tr("Save…"));
    addButton->setText(tr("Add ink"));
    loadButton->setObjectName(QStringLiteral("paletteLoad"));
    saveButton->setObjectName(QStringLiteral("paletteSave"));
    addButton->setObjectName(QStringLiteral("paletteAdd"));
    addButton->setToolTip(tr("Put the current ink into this palette"));
    auto* buttons = new QHBoxLayout;
    for (QToolButton* b : {loadButton, saveButton, addButton})
        buttons->addWidget(b);
    buttons->addStretch();
    auto* content = new QWidget;
    auto* layout = new QVBoxLayout(content);
    layout->addWidget(m_choice);
    layout->addWidget(m_swatches, 1);
    layout->addLayout(buttons);
    setWidget(content);

    for (const model::Palette& p : m_palettes)
        m_choice->addItem(p.name);
    connect(m_choice, &QComboBox::currentIndexChanged, this, &PaletteDock::showPalette);
    connect(m_swatches, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
        emit colourPicked(item->data(Qt::UserRole).value<QColor>());
    });
    connect(loadButton, &QToolButton::clicked, this, &PaletteDock::chooseFile);
    connect(saveButton, &QToolButton::clicked, this, &PaletteDock::saveShown);
    connect(addButton, &QToolButton::clicked, this, &PaletteDock::addInk);
    showPalette(0);
}

QStringList PaletteDock::loadRemembered()
{
    const QStringList remembered = QSettings().value(filesKey).toStringList();
    QSettings().remove(filesKey);
    QStringList errors;
    for (const QString& path : remembered)
        if (const QString error = add(path); !error.isEmpty())
            errors << error;
    return errors;
}

void PaletteDock::setInkColour(const QColor& colour)
{
    m_ink = colour;
    markInk();
}

void PaletteDock::load(const QString& path)
{
    if (const QString error = add(path); !error.isEmpty())
        emit problem(tr("Cannot load the palette"), error);
}

QString PaletteDock::add(const QString& path)
{
    model::PaletteReadResult read = model::readPaletteFile(path);
    if (!read.ok())
        return read.error;
    if (read.palette.name.isEmpty())
        read.palette.name = QFileInfo(path).completeBaseName();
    m_palettes.push_back(std::move(read.palette));
    m_choice->addItem(m_palettes.back().name);
    m_choice->setCurrentIndex(m_choice->count() - 1);
    QStringList remembered = QSettings().value(filesKey).toStringList();
    remembered.removeAll(path);
    QSettings().setValue(filesKey, remembered << path);
    return {};
}

void PaletteDock::showPalette(int index)
{
    if (index < 0)
        return;
    m_current = index;
    m_swatches->clear();
    for (const model::PaletteColour& c : shown().colours) {
        auto* item = new QListWidgetItem(swatch(c.colour), QString(), m_swatches);
        item->setData(Qt::UserRole, c.colour);
        item->setToolTip(c.name.isEmpty() ? c.colour.name() : QStringLiteral("%1 (%2)").arg(c.name, c.colour.name()));
    }
    markInk();
}

void PaletteDock::markInk()
{
    for (int row = 0; row < m_swatches->count(); ++row) {
        QListWidgetItem* item = m_swatches->item(row);
        if (item->data(Qt::UserRole).value<QColor>() == m_ink) {
            m_swatches->setCurrentItem(item);
            return;
        }
    }
    m_swatches->clearSelection();
}

void PaletteDock::chooseFile()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Load palette"), documentsFolder(), tr("GIMP palettes (*.gpl)"));
    if (!path.isEmpty())
        load(path);
}

void PaletteDock::saveShown()
{
    const QString suggested = QDir(documentsFolder()).filePath(shown().name + QStringLiteral(".gpl"));
    const QString path = QFileDialog::getSaveFileName(this, tr("Save palette"), suggested, tr("GIMP palettes (*.gpl)"));
    if (path.isEmpty())
        return;
    if (const QString error = model::writePaletteFile(shown(), path); !error.isEmpty())
        emit problem(tr("Cannot save the palette"), error);
}

void PaletteDock::addInk()
{
    m_palettes[std::size_t(m_current)].colours.push_back({m_ink, {}});
    showPalette(m_current);
}

} // namespace vf::app
