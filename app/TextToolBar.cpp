#include "app/TextToolBar.h"

#include <QDoubleSpinBox>
#include <QFontInfo>
#include <QFontDialog>
#include <QLabel>
#include <QPushButton>
#include <QSettings>

namespace vf::app {
namespace {

const QString fontKey = QStringLiteral("text/font");
constexpr double kDefaultSize = 0.1;  // a tenth of a unit canvas: big enough to read, room to flow

// The family's regular face, named: the style its name alone is drawn in. A font named by its
// family alone leaves the style to the font dialog, which asks for a style called "Normal", and
// where the family has none (DejaVu Sans: Book) opens on the first it lists (Oblique).
QFont regularFont(const QString& family)
{
    QFont font(family);
    font.setStyleName(QFontInfo(font).styleName());
    return font;
}

} // namespace

TextToolBar::TextToolBar(QWidget* parent)
    : QToolBar(tr("Text"), parent)
    , m_fontButton(new QPushButton(this))
    , m_size(new QDoubleSpinBox(this))
{
    setObjectName(QStringLiteral("textOptions"));
    m_fontButton->setObjectName(QStringLiteral("textFont"));
    m_fontButton->setToolTip(tr("Typeface of the Text tool"));
    connect(m_fontButton, &QPushButton::clicked, this, &TextToolBar::chooseFont);
    m_size->setObjectName(QStringLiteral("textSize"));
    m_size->setToolTip(tr("Height of the letters' em square, in canvas units"));
    m_size->setDecimals(4);
    m_size->setRange(0.001, 1000.0);
    m_size->setSingleStep(0.01);
    m_size->setValue(kDefaultSize);
    connect(m_size, &QDoubleSpinBox::valueChanged, this, &TextToolBar::changed);
    addWidget(m_fontButton);
    addWidget(new QLabel(tr(" Size: "), this));
    addWidget(m_size);

    QFont saved;
    const QString savedText = QSettings().value(fontKey).toString();
    setTextFont(!savedText.isEmpty() && saved.fromString(savedText) ? saved : regularFont(QStringLiteral("DejaVu Sans")));
}

double TextToolBar::size() const
{
    return m_size->value();
}

void TextToolBar::chooseFont()
{
    bool ok = false;
    const QFont font = QFontDialog::getFont(&ok, m_font, this, tr("Text font"));
    if (!ok)
        return;
    setTextFont(font);
    QSettings().setValue(fontKey, font.toString());
    emit changed();
}

void TextToolBar::setTextFont(const QFont& font)
{
    m_font = font;
    m_fontButton->setText((font.family() + QLatin1Char(' ') + font.styleName()).trimmed() + QStringLiteral("…"));
}

} // namespace vf::app
