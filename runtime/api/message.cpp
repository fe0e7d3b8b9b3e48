// Diagnostics of fxkit's front end, compiler and runtime as public Messages.
#include "api_state.h"
#include "fx/diagnostic_render.h"

namespace fxkit {

bool has_errors(const std::vector<Message>& messages) {
  for (const Message& m : messages)
    if (m.severity == Severity::error) return true;
  return false;
}

namespace detail {

Message to_message(const fx::Diagnostic& d, const fx::SourceManager* sources) {
  Message m;
  m.severity = d.severity == fx::Severity::error     ? Severity::error
               : d.severity == fx::Severity::warning ? Severity::warning
                                                     : Severity::note;
  m.code = d.id;
  m.text = d.message;
  if (sources && d.range.begin.valid()) {
    const fx::PresumedLocation at = sources->presumed(d.range.begin);
    m.file = std::string(at.file);
    m.line = at.line;
    m.column = at.column;
  }
  if (sources) {
    m.rendered = fx::render_text(d, *sources);  // as `fxkit check` prints it
  } else {
    m.rendered = std::string(fx::to_string(d.severity)) + ": " + m.text + " [" + m.code + "]\n";
  }
  return m;
}

Message to_message(fx::Severity severity, std::string code, std::string text) {
  fx::Diagnostic d;
  d.severity = severity;
  d.id = std::move(code);
  d.message = std::move(text);
  return to_message(d, nullptr);
}

std::vector<Message> to_messages(const std::vector<fx::Diagnostic>& ds, const fx::SourceManager* sources) {
  std::vector<Message> out;
  out.reserve(ds.size());
  for (const fx::Diagnostic& d : ds) out.push_back(to_message(d, sources));
  return out;
}

void EffectState::keep_problems() {
  for (const fx::Diagnostic& d : sink.diagnostics()) problems.push_back(to_message(d, nullptr));
  sink.clear();
  if (problems.size() > kRecentProblems) problems.erase(problems.begin(), problems.end() - kRecentProblems);
}

}  // namespace detail
}  // namespace fxkit
