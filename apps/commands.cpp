// The subcommands, in the order `haptex --help` lists them.
#include "apps/command.hpp"

namespace haptex::apps {

std::unique_ptr<Command> make_convert_command();
std::unique_ptr<Command> make_info_command();
std::unique_ptr<Command> make_qa_command();
std::unique_ptr<Command> make_view_command();
std::unique_ptr<Command> make_capture_command();
std::unique_ptr<Command> make_synth_command();
std::unique_ptr<Command> make_align_command();
std::unique_ptr<Command> make_merge_command();
std::unique_ptr<Command> make_split_command();
std::unique_ptr<Command> make_train_command();
std::unique_ptr<Command> make_predict_command();
std::unique_ptr<Command> make_windows_command();
std::unique_ptr<Command> make_evaluate_command();
std::unique_ptr<Command> make_trajectory_command();
std::unique_ptr<Command> make_render_command();
std::unique_ptr<Command> make_play_command();

std::vector<std::unique_ptr<Command>> all_commands() {
  std::vector<std::unique_ptr<Command>> commands;
  commands.push_back(make_convert_command());
  commands.push_back(make_info_command());
  commands.push_back(make_capture_command());
  commands.push_back(make_synth_command());
  commands.push_back(make_align_command());
  commands.push_back(make_merge_command());
  commands.push_back(make_split_command());
  commands.push_back(make_qa_command());
  commands.push_back(make_view_command());
  commands.push_back(make_train_command());
  commands.push_back(make_predict_command());
  commands.push_back(make_windows_command());
  commands.push_back(make_evaluate_command());
  commands.push_back(make_trajectory_command());
  commands.push_back(make_render_command());
  commands.push_back(make_play_command());
  return commands;
}

}  // namespace haptex::apps
