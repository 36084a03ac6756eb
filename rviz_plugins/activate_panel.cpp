#include "rviz_plugins/activate_panel.h"

#include <std_msgs/Empty.h>

#include <QDir>
#include <QFileDialog>
#include <QLabel>
#include <QPushButton>
#include <QTime>
#include <QVBoxLayout>
#include <pluginlib/class_list_macros.hpp>

#include "kinematic_coverage/SaveMission.h"

namespace kinematic_coverage::rviz_plugins {

ActivatePanel::ActivatePanel(QWidget* parent)
    : rviz::Panel(parent),
      publisher_(node_.advertise<std_msgs::Empty>("activate", 1)),
      save_client_(
          node_.serviceClient<kinematic_coverage::SaveMission>("coverage_planner/save_mission")),
      status_label_(new QLabel("Set the start and the goal, then activate.")) {
  auto* button = new QPushButton("&Activate");
  button->setToolTip(
      QString("Publish std_msgs/Empty on %1 (Alt+A): coverage_planner plans a coverage path "
              "with the current polygon, start and goal.")
          .arg(QString::fromStdString(publisher_.getTopic())));
  auto* save_button = new QPushButton("&Save mission...");
  save_button->setToolTip(
      QString("Save the polygon, start and goal that coverage_planner holds, with its "
              "parameters, as a mission file for coverage_tool plan and mission.launch (%1).")
          .arg(QString::fromStdString(save_client_.getService())));
  status_label_->setWordWrap(true);
  auto* layout = new QVBoxLayout;
  layout->addWidget(button);
  layout->addWidget(save_button);
  layout->addWidget(status_label_);
  layout->addStretch();
  setLayout(layout);
  connect(button, &QPushButton::clicked, this, &ActivatePanel::sendActivate);
  connect(save_button, &QPushButton::clicked, this, &ActivatePanel::saveMission);
}

void ActivatePanel::saveMission() {
  const QString service = QString::fromStdString(save_client_.getService());
  if (!save_client_.waitForExistence(ros::Duration(0.5))) {
    status_label_->setText(QString("Nothing offers %1: is coverage_planner running?").arg(service));
    return;
  }
  const QString path = QFileDialog::getSaveFileName(
      this, "Save the mission", QDir::home().filePath("mission.yaml"), "Mission files (*.yaml)");
  if (path.isEmpty()) return;
  kinematic_coverage::SaveMission save;
  save.request.path = path.toStdString();
  if (!save_client_.call(save)) {
    status_label_->setText(QString("The call to %1 failed.").arg(service));
    return;
  }
  status_label_->setText(save.response.success ? QString("Mission saved to %1.").arg(path)
                                               : QString::fromStdString(save.response.message));
}

void ActivatePanel::sendActivate() {
  publisher_.publish(std_msgs::Empty());
  const QString time = QTime::currentTime().toString("HH:mm:ss");
  const QString topic = QString::fromStdString(publisher_.getTopic());
  if (publisher_.getNumSubscribers() == 0) {
    status_label_->setText(
        QString("Activated at %1, but nothing subscribes to %2: is coverage_planner running?")
            .arg(time, topic));
  } else {
    status_label_->setText(QString("Activated at %1 on %2.").arg(time, topic));
  }
}

}  // namespace kinematic_coverage::rviz_plugins

PLUGINLIB_EXPORT_CLASS(kinematic_coverage::rviz_plugins::ActivatePanel, rviz::Panel)
