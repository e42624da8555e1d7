// A model's parameters (`param` globals, vvlib/model/abi.hpp): listed, read
// and set from text, checked against their type and range. The host keeps
// the values a user gave (--set, the panel) and gives them to every fresh
// instance of the model, before its start block.
#pragma once

#include <string>
#include <vector>

#include <model/abi.hpp>

namespace vvi {

class session;

std::vector<const vv_param_entry*> parameters_of(const session& s);
const vv_param_entry* find_parameter(const session& s, const std::string& name);

//! The value as text, as short as reads back exactly ("0.1", "true", "3").
std::string parameter_text(const vv_param_entry& p);
//! The value as a number (bool: 0 or 1), for sliders.
double parameter_number(const vv_param_entry& p);
//! "rate double 0.5 [0, 1]": one line of --list-params.
std::string parameter_line(const vv_param_entry& p);

//! Sets the parameter from text: "" when done, else why not (the text is
//! not of the parameter's type, or lies outside its range); the value is
//! unchanged then.
std::string set_parameter(const vv_param_entry& p, const std::string& text);

//! A value the user gave a parameter, by name (and by type once the
//! parameter has been seen: a reload keeps it only while both match).
struct parameter_setting {
  std::string name, type, text;
};

//! Applies settings to a freshly loaded model. A setting the model has no
//! parameter for, or whose text does not fit, is an error when its type is
//! not known yet (--set on the command line: "" when all applied, else one
//! line naming the model file and the parameter); a setting from before a
//! reload is dropped instead when its parameter is gone or changed type.
//! Known types are filled in.
std::string apply_parameter_settings(const session& s, std::vector<parameter_setting>& settings,
                                     const std::string& model_file);

}  // namespace vvi
