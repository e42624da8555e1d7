// The words of the report pipe between a model's process and its
// supervisor, one place for both sides: fault_guard writes them (from
// signal handlers too: plain character arrays), report_reader reads them.
// A line is a word, a space and the rest.
#pragma once

namespace vvi::report_words {

// What the model is doing.
inline constexpr char begin[] = "begin";        //!< begin WHAT STEP: an announced activity began
inline constexpr char thread[] = "thread";      //!< thread TID: the thread that runs it
inline constexpr char done[] = "done";          //!< done WHAT STEP: it ended normally
inline constexpr char activity[] = "activity";  //!< activity WHAT STEP: what ran when the report was made

// Reports, each ended by `end`.
inline constexpr char crash[] = "crash";          //!< crash SIGNAL: a fatal signal's report follows
inline constexpr char exception[] = "exception";  //!< exception TEXT: what an uncaught exception said
inline constexpr char sample[] = "sample";        //!< sample WHY NUMBER: a stack sample follows
inline constexpr char pc[] = "pc";                //!< pc HEX: the interrupted instruction
inline constexpr char frame[] = "frame";          //!< frame HEX: a return address
inline constexpr char map[] = "map";              //!< map LINE: a /proc/self/maps line of a file
inline constexpr char end[] = "end";              //!< the report is whole

// Why a sample was sent.
inline constexpr char running[] = "running";  //!< asked for, while an activity runs
inline constexpr char idle[] = "idle";        //!< asked for, nothing runs
inline constexpr char exit_call[] = "exit";   //!< the model called exit() inside a block

// Files.
inline constexpr char module[] = "module";    //!< module LOADED<TAB>ORIGINAL: a plugin's private copy
inline constexpr char writing_in[] = "writing-in";  //!< writing-in FOLDER (a temporary is about to be made there)
inline constexpr char writing[] = "writing";  //!< writing TEMPORARY<TAB>TARGET
inline constexpr char written[] = "written";  //!< written TEMPORARY

// The viewer's state record (control/state_record.hpp).
inline constexpr char state[] = "state";

}  // namespace vvi::report_words
