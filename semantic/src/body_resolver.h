// Resolves the identifiers of one function body (a token range the parser kept for the
// shader compiler) against its parameters, its locals by scope, its class's members and
// the effect's globals, and types member accesses and swizzles. Private to fxkit_semantic.
#pragma once
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "fx/semantic_model.h"

namespace fx::semantic {

class BodyResolver {
 public:
  BodyResolver(SemanticModel& model, const ast::Function& function);
  // Walks the body once, adding its locals, references and findings to the model.
  void run();

 private:
  // A declaration statement being read: more declarators may follow a `,`.
  struct Declaration {
    bool active = false;
    ShaderType type;
    uint32_t type_first = 0;
    int parens = 0;  // the parenthesis depth it started at (`for (int i = 0, j = 1; ...)`)
    int braces = 0;  // `{ }` of initializer lists inside it
  };

  bool models_body() const;
  void declare_parameters();
  bool try_declaration(uint32_t& i);
  void declare_local(uint32_t name_token, const ShaderType& type, uint32_t type_first);
  uint32_t after_array_sizes(uint32_t i, uint32_t* rank) const;  // i at `[`: the token after the sizes
  uint32_t array_rank_after(uint32_t i) const;
  uint32_t skip_template_arguments(uint32_t i) const;
  uint32_t after_annotations(uint32_t i) const;
  bool skip_annotations_of(uint32_t name_token);
  bool is_type_name(std::string_view name) const;
  const Symbol* lookup(std::string_view name) const;
  const Symbol* class_member(const ast::Struct& c, std::string_view name, int depth) const;  // or of its bases
  void open_scope();
  void close_scope(uint32_t at);
  void resolve_identifier(uint32_t i);
  void resolve_member(uint32_t i);
  void add_reference(uint32_t i, const Symbol* symbol, const ShaderType& type);
  bool quiet(uint32_t i) const;
  void report_unknown_identifier(uint32_t i);
  void report_unknown_member(uint32_t i, const ShaderType& base);

  SemanticModel& model_;
  const ast::Function& function_;
  const std::vector<Token>& tokens_;
  uint32_t first_ = 0, last_ = 0;
  const ast::Struct* owner_ = nullptr;              // a method's class
  bool modelled_ = true;                            // false: resolve, but report nothing
  std::vector<Symbol*> scope_;                      // parameters and locals in view, innermost last
  std::vector<size_t> scope_marks_;                 // scope_.size() at each open `{`
  std::unordered_map<uint32_t, ShaderType> typed_;  // token (identifier or `]`) -> value type
  std::vector<uint32_t> brackets_;                  // open `[`
  Declaration declaration_;
  uint32_t annotations_first_ = 0, annotations_end_ = 0;  // a declarator's `< ... >`, skipped
  int parens_ = 0;
  std::vector<bool> control_parens_;  // per open `(`: it opened a for/if/while/switch header
};

}  // namespace fx::semantic
