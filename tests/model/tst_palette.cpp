// GIMP .gpl palettes (model/Palette): files as GIMP, Krita and Inkscape write them, every palette
// Inkscape ships, GIMP's layout on writing, round trips, and one-line refusals naming the line.
#include "model/Palette.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace vf::model;

class TestPalette : public QObject {
    Q_OBJECT

private slots:
    void readsGimpKritaAndInkscapeLayouts_data()
    {
        QTest::addColumn<QByteArray>("file");
        // GIMP: tab before the name, "Untitled" names, a comment line of its own.
        QTest::newRow("gimp") << QByteArray("GIMP Palette\nName: Bears\n#\n  8   8   8\tgrey3\n 68  44  44\tUntitled\n");
        // Krita: Columns, names with spaces after a tab.
        QTest::newRow("krita") << QByteArray("GIMP Palette\nName: Bears\nColumns: 2\n#\n8 8 8\tgrey3\n68 44 44\tUntitled\n");
        // Inkscape: names after two spaces; Windows line ends and a byte order mark.
        QTest::newRow("inkscape, crlf, bom")
            << QByteArray("\xef\xbb\xbfGIMP Palette\r\nName: Bears\r\n# generated\r\n  8   8   8  grey3\r\n 68  44  44  Untitled\r\n");
    }

    void readsGimpKritaAndInkscapeLayouts()
    {
        QFETCH(QByteArray, file);
        const PaletteReadResult read = parseGpl(file, QStringLiteral("bears.gpl"));
        QVERIFY2(read.ok(), qPrintable(read.error));
        QCOMPARE(read.palette.name, QStringLiteral("Bears"));
        QCOMPARE(read.palette.colours.size(), std::size_t(2));
        QCOMPARE(read.palette.colours[0], (PaletteColour{QColor(8, 8, 8), QStringLiteral("grey3")}));
        QCOMPARE(read.palette.colours[1], (PaletteColour{QColor(68, 44, 44), QStringLiteral("Untitled")}));
    }

    void readsEveryPaletteInkscapeShips()
    {
        const QDir folder(QStringLiteral("/usr/share/inkscape/palettes"));
        const QStringList files = folder.entryList({QStringLiteral("*.gpl")});
        if (files.isEmpty())
            QSKIP("Inkscape's palettes are not installed (scripts/setup installs Inkscape)");
        for (const QString& name : files) {
            const PaletteReadResult read = readPaletteFile(folder.filePath(name));
            QVERIFY2(read.ok(), qPrintable(read.error));
            QVERIFY2(!read.palette.colours.empty(), qPrintable(name));
        }
        const PaletteReadResult inkscape = readPaletteFile(folder.filePath(QStringLiteral("inkscape.gpl")));
        QCOMPARE(inkscape.palette.name, QStringLiteral("Inkscape default"));
        QCOMPARE(inkscape.palette.columns, 27);
        QCOMPARE(inkscape.palette.colours.front(), (PaletteColour{Qt::black, QStringLiteral("Black")}));
    }

    void writesGimpsLayout()
    {
        const Palette palette{QStringLiteral("Two\tinks"), 2, {{QColor(8, 8, 8), QStringLiteral("grey3")}, {QColor(255, 0, 10), {}}}};
        QCOMPARE(gplBytes(palette), QByteArray("GIMP Palette\nName: Two inks\nColumns: 2\n#\n  8   8   8\tgrey3\n255   0  10\t\n"));
    }

    void builtInPalettesRoundTripThroughFiles()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QCOMPARE(builtInPalettes().size(), std::size_t(2));
        for (const Palette& palette : builtInPalettes()) {
            QVERIFY(palette.colours.size() >= 8);
            const QString path = dir.filePath(palette.name + QStringLiteral(".gpl"));
            QCOMPARE(writePaletteFile(palette, path), QString());
            const PaletteReadResult read = readPaletteFile(path);
            QVERIFY2(read.ok(), qPrintable(read.error));
            QCOMPARE(read.palette, palette);
        }
    }

    void refusesWhatItWouldGuessAt_data()
    {
        QTest::addColumn<QByteArray>("file");
        QTest::addColumn<QString>("error");
        QTest::newRow("empty") << QByteArray() << "bad.gpl: line 1: not a GIMP palette";
        QTest::newRow("other format") << QByteArray("JASC-PAL\n0100\n") << "bad.gpl: line 1: not a GIMP palette";
        QTest::newRow("out of range") << QByteArray("GIMP Palette\n0 0 0\n300 0 0 hot\n") << "bad.gpl: line 3: red '300'";
        QTest::newRow("negative") << QByteArray("GIMP Palette\n0 -1 0\n") << "bad.gpl: line 2: green '-1'";
        QTest::newRow("not a number") << QByteArray("GIMP Palette\n0 0 blue\n") << "bad.gpl: line 2: blue 'blue'";
        QTest::newRow("two numbers") << QByteArray("GIMP Palette\n\n12 34\n") << "bad.gpl: line 3: a colour line needs";
        QTest::newRow("columns") << QByteArray("GIMP Palette\nColumns: many\n") << "bad.gpl: line 2: Columns must be";
        QByteArray many = "GIMP Palette\n";
        for (int i = 0; i <= limits::maxPaletteColours; ++i)
            many += "1 2 3\n";
        QTest::newRow("too many") << many << "bad.gpl: line 65538: more than";
    }

    void refusesWhatItWouldGuessAt()
    {
        QFETCH(QByteArray, file);
        QFETCH(QString, error);
        const PaletteReadResult read = parseGpl(file, QStringLiteral("bad.gpl"));
        QVERIFY2(read.error.startsWith(error), qPrintable(read.error));
        QVERIFY(!read.error.contains(u'\n'));
        QVERIFY(read.palette.colours.empty());
    }

    // Saving goes through the atomic writer every file uses (model/AtomicFile, whose failures on a
    // full disk tst_cli_disks checks); here, a folder that is not there.
    void aFailedWriteSaysWhyInOneLine()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("missing/inks.gpl"));
        const QString error = writePaletteFile(builtInPalettes()[0], path);
        QVERIFY2(error.startsWith(path), qPrintable(error));
        QVERIFY(!error.contains(u'\n'));
        QVERIFY(!QFile::exists(path));
    }
};

QTEST_MAIN(TestPalette)
#include "tst_palette.moc"
