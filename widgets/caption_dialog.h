#pragma once
// Lesson > Edit Caption: a step's caption in each language the lessons are written in
// (English, Portuguese, German; the UI's language first), as markdown, one field each.

#include <QDialog>
#include <QMap>

class QPlainTextEdit;
class QTabWidget;

namespace lb {

class CaptionDialog : public QDialog
{
    Q_OBJECT
public:
    // `captions`: by language code; `uiLanguage`: the UI's ("en", "pt", "de"), shown first.
    // `maxCharacters`: the most one language may hold (longer is refused with a message).
    CaptionDialog(const QMap<QString, QString> &captions, const QString &uiLanguage,
                  int maxCharacters, QWidget *parent = nullptr);
    // What the fields hold (empty fields left out), with any other language as it was.
    QMap<QString, QString> captions() const;
    QPlainTextEdit *field(const QString &language) const { return m_fields.value(language); }
    QTabWidget *tabs() const { return m_tabs; }

    void accept() override; // not while a field is over the limit

private:
    QMap<QString, QString> m_others; // languages this dialog has no field for, kept
    QMap<QString, QPlainTextEdit *> m_fields;
    QTabWidget *m_tabs;
    int m_max;
};

} // namespace lb
