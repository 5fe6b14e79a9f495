#include "editor/palette.h"

#include <QHeaderView>
#include <QLineEdit>
#include <QMenu>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace lg::editor {

static QString text_of(const std::string& s) {
  return QString::fromStdString(s);
}

Palette::Palette(const Registry& registry, QWidget* parent)
    : QWidget(parent), search_(new QLineEdit(this)), tree_(new QTreeWidget(this)) {
  search_->setPlaceholderText(tr("Search nodes…"));
  search_->setClearButtonEnabled(true);
  tree_->setHeaderHidden(true);
  tree_->setRootIsDecorated(true);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(search_);
  layout->addWidget(tree_);

  std::map<std::string, QTreeWidgetItem*> categories;
  for (const NodeSchema* schema : registry.all()) {
    QTreeWidgetItem*& category = categories[schema->category];
    if (!category) {
      category = new QTreeWidgetItem(tree_, {text_of(schema->category)});
      category->setFlags(Qt::ItemIsEnabled);
      QFont bold = category->font(0);
      bold.setBold(true);
      category->setFont(0, bold);
    }
    auto* item = new QTreeWidgetItem(category, {text_of(schema->type)});
    item->setData(0, Qt::UserRole, text_of(schema->type));
    item->setToolTip(0, text_of(schema->doc));
  }
  tree_->expandAll();

  connect(search_, &QLineEdit::textChanged, this, &Palette::set_filter);
  connect(tree_, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
    if (const QString type = item->data(0, Qt::UserRole).toString(); !type.isEmpty()) emit add_requested(type);
  });
  // Enter in the search box adds the first match.
  connect(search_, &QLineEdit::returnPressed, this, [this] {
    if (const QStringList types = visible_types(); !types.isEmpty()) emit add_requested(types.front());
  });
}

void Palette::set_filter(const QString& text) {
  if (search_->text() != text) search_->setText(text);
  for (int c = 0; c < tree_->topLevelItemCount(); ++c) {
    QTreeWidgetItem* category = tree_->topLevelItem(c);
    bool any = false;
    for (int i = 0; i < category->childCount(); ++i) {
      QTreeWidgetItem* item = category->child(i);
      const bool match =
          item->text(0).contains(text, Qt::CaseInsensitive) || item->toolTip(0).contains(text, Qt::CaseInsensitive);
      item->setHidden(!match);
      any |= match;
    }
    category->setHidden(!any);
  }
}

QStringList Palette::visible_types() const {
  QStringList types;
  for (int c = 0; c < tree_->topLevelItemCount(); ++c)
    for (int i = 0; i < tree_->topLevelItem(c)->childCount(); ++i)
      if (QTreeWidgetItem* item = tree_->topLevelItem(c)->child(i); !item->isHidden())
        types << item->data(0, Qt::UserRole).toString();
  return types;
}

void fill_node_menu(QMenu& menu, const Registry& registry) {
  std::map<std::string, QMenu*> categories;
  for (const NodeSchema* schema : registry.all()) {
    QMenu*& sub = categories[schema->category];
    if (!sub) sub = menu.addMenu(text_of(schema->category));
    QAction* action = sub->addAction(text_of(schema->type));
    action->setData(text_of(schema->type));
    action->setToolTip(text_of(schema->doc));
  }
}

}  // namespace lg::editor
