#pragma once
//! \file
//! The limits hyst puts on what one input may cost. Every one of them is stated here, and every
//! error that hits one names the limit and its value ("the limit is ..."). docs/reliability.md
//! lists them too.

#include <cstddef>

namespace hyst::io::limits {

//! Deepest nesting of arrays and objects in any JSON text hyst reads (model files, --options,
//! actuator configurations, Python dicts and lists converted to JSON). Model files need 3 levels;
//! the limit keeps every recursive walk over a document (printing, conversion) far from the end
//! of the stack.
inline constexpr std::size_t kMaxJsonDepth = 256;

//! Most bytes read from one input file (regular file, FIFO or device): 256 MiB. A longer input,
//! such as an endless stream, stops at this limit with an error naming the file.
inline constexpr std::size_t kMaxInputBytes = std::size_t{1} << 28;

//! Most bytes one MAT-file variable may hold once inflated (its samples as doubles): 256 MiB,
//! i.e. 33 554 432 samples. Next to this, a variable may claim no more than 2048 x the file's
//! size (zlib's best ratio is 1032:1).
inline constexpr std::size_t kMaxMatVariableBytes = std::size_t{1} << 28;

//! Most samples a count derived from a user-given number may ask for (resampling steps, grid
//! sizes): 10 000 000. The count is checked as a double before it becomes an integer.
inline constexpr double kMaxDerivedSamples = 1e7;

//! Most curves of one FORC file: 100 000 (measured runs have 50 to 1 000), and most data
//! points of one FORC file: 10 000 000 (80 MB per column as doubles; measured runs have 5 000
//! to 200 000). They bound what a file of kMaxInputBytes may make the reader allocate.
inline constexpr std::size_t kMaxForcCurves = 100000;
inline constexpr std::size_t kMaxForcPoints = 10000000;

//! Most values of one NumPy array (a .npy file or an .npz member): 33 554 432 (2^25), i.e.
//! 256 MiB as doubles, the same as one MAT variable. Checked on the shape a header states,
//! before anything is allocated. A .npy file is also bounded by kMaxInputBytes as a whole.
inline constexpr std::size_t kMaxNumpyValues = std::size_t{1} << 25;

//! Longest header of a .npy file: 10 000 bytes, the default limit of NumPy's own reader
//! (numpy.load's max_header_size). Plain float arrays have headers of 118 to 246 bytes.
inline constexpr std::size_t kMaxNpyHeaderBytes = 10000;

//! Most bytes one .npz member may inflate to: the largest .npy file the two limits above allow
//! (a preamble of 12 bytes, the longest header, kMaxNumpyValues float64 values), about 256 MiB.
//! Checked against the size the archive claims before reading, and again while inflating.
inline constexpr std::size_t kMaxNpzMemberBytes =
    12 + kMaxNpyHeaderBytes + kMaxNumpyValues * sizeof(double);

//! Most values of one array in a model file (thresholds, weights, plays, relays, a state's play
//! outputs): 16 777 216 (2^24). The largest array a model needs, the weights of a Preisach
//! model of 4096 levels, has 8 390 656. Checked on the array's length before it is converted.
inline constexpr std::size_t kMaxModelArrayValues = std::size_t{1} << 24;

//! Most records one fit of several records takes (`hyst fit --tables`, Python fit_records): 1 000
//! (aixACCT exports hold about ten tables). Checked on the count before any record is read or
//! copied; the records' samples together are bounded by kMaxNumpyValues as well.
inline constexpr std::size_t kMaxFitRecords = 1000;

//! Most parameters of one hysteresis channel of a hysteretic LFR model file (a PI model's
//! thresholds and weights): 1 000. Every channel steps once per sample of every period the search
//! for the periodic state runs (up to 1 000 periods): a channel of 200 000 plays took 114 s to
//! score; the fits make 6 plays.
inline constexpr std::size_t kMaxLfrChannelParameters = 1000;

}  // namespace hyst::io::limits
