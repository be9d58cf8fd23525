// The fusion node generated from one configuration header. sf_add_filter() compiles this
// file once per header, with -DSF_CONFIG_HEADER="path/to/header.h".
#ifndef SF_CONFIG_HEADER
#error "SF_CONFIG_HEADER is not defined: build fusion nodes with sf_add_filter(<name> <header>)"
#endif
#include SF_CONFIG_HEADER

#include <sf_filter/config/configuration.hpp>

// A configuration mistake has been reported above; generating the node would only add
// follow-up errors.
#if SF_CONFIG_OK

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <ros/message_traits.h>
#include <ros/ros.h>

#include "sf_filter/node/filter_binding.hpp"
#include "sf_filter/node/frame_aligner.hpp"
#include "sf_filter/node/frame_alignment_config.hpp"
#include "sf_filter/node/fusion_node.hpp"
#include "sf_filter/node/ros_parameters.hpp"
#include "sf_filter/replay/bag_replay.hpp"
#include "sf_filter/replay/contained_run.hpp"
#include "sf_filter/replay/library_messages.hpp"
#include "sf_filter/replay/replay_frame_aligner.hpp"

#ifdef POSE_OUT
#include <boost/preprocessor/seq/elem.hpp>
#include <boost/preprocessor/seq/size.hpp>
static_assert(BOOST_PP_SEQ_SIZE(POSE_OUT) == 3,
              "POSE_OUT: expected (x index)(y index)(heading index), 3 entries");
static_assert(BOOST_PP_SEQ_ELEM(0, POSE_OUT) < sf_config::kStateSize &&
                  BOOST_PP_SEQ_ELEM(1, POSE_OUT) < sf_config::kStateSize &&
                  BOOST_PP_SEQ_ELEM(2, POSE_OUT) < sf_config::kStateSize,
              "POSE_OUT: every state index must be < n (the state size)");
#endif

namespace {

using Node = sf_filter::FusionNode<sf_filter::generated::Filter>;

template <class Message>
double stampOf(const Message& msg) {
  if constexpr (ros::message_traits::HasHeader<Message>::value) {
    return msg.header.stamp.toSec();
  } else {
    return std::numeric_limits<double>::quiet_NaN();
  }
}

/// "topic field" per input; "topic member" for a FRAME_ALIGNED_INPUTS one.
std::vector<std::string> inputNames() {
  std::vector<std::string> names;
  sf_config::forEachInput([&](auto in) {
    using In = decltype(in);
    using Align = sf_config::FrameAlignment<In::index>;
    if constexpr (Align::aligned) {
      names.push_back(std::string(In::topic) + " " + std::string(Align::member));
    } else {
      names.push_back(std::string(In::topic) + " " + std::string(In::field));
    }
  });
  return names;
}

/// `aligner`: the node's FrameAligner or the replay's ReplayFrameAligner (nullptr without
/// FRAME_ALIGNED_INPUTS).
template <class Aligner>
sf_filter::NodeDescription describe(const Aligner* aligner) {
  sf_filter::NodeDescription d;
  d.method = sf_config::kMethodName;
  d.inputs = inputNames();
  sf_config::forEachInput([&](auto in) {
    using Align = sf_config::FrameAlignment<decltype(in)::index>;
    if constexpr (Align::aligned) {
      d.inputs[Align::input_index] +=
          " rotated into " + aligner->baseFrame() + ", " + std::string(Align::axis_name);
    }
  });
  sf_config::forEachControl([&](auto in) {
    using In = decltype(in);
    d.controls.push_back(std::string(In::topic) + " " + std::string(In::field));
  });
  sf_config::forEachOutput([&](auto out) {
    using Out = decltype(out);
    d.outputs.emplace_back(std::string(Out::topic), Out::state_index);
  });
#ifdef POSE_OUT
  d.pose = std::array<int, 3>{BOOST_PP_SEQ_ELEM(0, POSE_OUT), BOOST_PP_SEQ_ELEM(1, POSE_OUT),
                              BOOST_PP_SEQ_ELEM(2, POSE_OUT)};
#endif
  return d;
}

/// What the configured inputs and method can do, for checking run-time policy overrides.
sf_filter::InputCapabilities inputCapabilities() {
  sf_filter::InputCapabilities can;
  can.canPredict = estimation::HasMeasurementPrediction<sf_filter::generated::Filter>::value;
  can.hasStamp.assign(sf_config::kInputHasStamp.begin(), sf_config::kInputHasStamp.end());
  can.names = inputNames();
  return can;
}

/// The fusion core's options: the period and the per-input options with the lag [ms]; stamps
/// more than `maxFutureStampMs` ahead of the clock are dropped.
sf_filter::FusionCore<sf_filter::generated::Filter>::Options coreOptions(
    double periodMs, std::vector<sf_filter::InputOptions> inputs, double lagMs,
    double maxFutureStampMs = sf_filter::kDefaultMaxFutureStampMs) {
  sf_filter::FusionCore<sf_filter::generated::Filter>::Options options;
  options.period = periodMs / 1000.0;
  options.inputs = std::move(inputs);
  options.maxMeasurementLag = lagMs / 1000.0;
  options.maxFutureStamp = maxFutureStampMs / 1000.0;
  return options;
}

/// Component Align::axis of the aligned input's vector in the base frame; nullopt if it cannot
/// be rotated (the aligner has counted and reported it).
template <class Align, class Aligner, class Message>
std::optional<double> alignedValue(Aligner& aligner, const Message& msg) {
  if constexpr (Align::valid) {
    return aligner.align(Align::input_index, msg.header.frame_id, msg.header.stamp,
                         Align::vector(msg), Align::axis);
  } else {
    return std::nullopt;  // not built: a static_assert of the configuration reported why
  }
}

/// One subscription per distinct topic; its callback reads every field used from it. The
/// FRAME_ALIGNED_INPUTS read a component of a vector rotated into the base frame instead.
template <class Sink, class Aligner>
void subscribeInputs(Sink& node, Aligner* aligner) {
  sf_config::forEachInput([&](auto owner) {
    using Owner = decltype(owner);
    if constexpr (Owner::owns_subscription) {
      using Message = typename Owner::Message;
      node.template subscribe<Message>(
          std::string(Owner::topic), [aligner](const Message& msg, auto& n, double now) {
            sf_config::forEachInput([&](auto in) {
              using In = decltype(in);
              using Align = sf_config::FrameAlignment<In::index>;
              if constexpr (In::first_same_topic == Owner::index) {
                std::optional<double> variance;
                if constexpr (In::has_variance) variance = In::variance(msg);
                double value = 0.0;
                if constexpr (Align::aligned) {
                  const std::optional<double> rotated = alignedValue<Align>(*aligner, msg);
                  if (!rotated) return;  // dropped and counted by the aligner
                  value = *rotated;
                } else {
                  static_cast<void>(aligner);
                  value = In::value(msg);
                }
                n.measurement(In::index, now, value, variance, stampOf(msg));
              }
            });
          });
    }
  });
  sf_config::forEachControl([&](auto owner) {
    using Owner = decltype(owner);
    if constexpr (Owner::owns_subscription) {
      using Message = typename Owner::Message;
      node.template subscribe<Message>(std::string(Owner::topic),
                                       [](const Message& msg, auto& n, double) {
                                         sf_config::forEachControl([&](auto in) {
                                           using In = decltype(in);
                                           if constexpr (In::first_same_topic == Owner::index)
                                             n.control(In::index, In::value(msg));
                                         });
                                       });
    }
  });
}

/// One line with what became of every input's values, logged by the node at shutdown (the
/// soak test compares `received` with what its driver published).
template <class Core>
std::string inputCountersLine(const Core& core, const std::vector<std::string>& names) {
  std::ostringstream line;
  line << "input counters at shutdown:";
  for (sf_filter::Index i = 0; i < core.inputCount(); ++i) {
    const sf_filter::InputCounters& c = core.counters(i);
    line << (i ? ";" : "") << " input " << i << " (" << names.at(static_cast<std::size_t>(i))
         << "): received " << c.received << ", used " << c.used << ", dropped " << c.dropped()
         << ", gated " << c.gated;
  }
  return line.str();
}

/// The input index of a replay option: an integer (its range is checked by the override).
long inputIndex(const std::string& text) {
  std::size_t used = 0;
  long index = -1;
  try {
    index = std::stol(text, &used);
  } catch (const std::logic_error&) {
    used = 0;
  }
  if (used == 0 || used != text.size()) {
    throw std::invalid_argument("input index '" + text + "' is not an integer");
  }
  return index;
}

/// The replay summary's line per input: what it received, used, dropped (by reason), gated.
template <class Core>
void printInputCounters(const std::string& name, const Core& core) {
  for (sf_filter::Index i = 0; i < core.inputCount(); ++i) {
    const sf_filter::InputCounters& c = core.counters(i);
    std::cout << name << ": input " << i << ": " << c.received << " received, " << c.used
              << " used, dropped: " << sf_filter::dropReasons(c) << ", " << c.gated << " gated, "
              << c.timedOutPeriods << " periods timed out" << std::endl;
  }
}

/// Offline replay: `<node> --replay in.bag [--csv out.csv] [--bag out.bag] [options]`.
int replayMain(int argc, char** argv) {
  const std::string program = argv[0];
  const std::string usage =
      "usage: " + program +
      " --replay INPUT.bag [--csv OUT.csv] [--bag OUT.bag] [--name NODE]\n"
      "       [--estimation-period MS] [--scale-q FACTOR] [--scale-r FACTOR] [--seed N]\n"
      "       [--frame-id FRAME] [--child-frame-id FRAME] [--base-frame FRAME]\n"
      "       [--align INPUT=POLICY]... [--gate INPUT=THRESHOLD]... [--align-by-stamp INPUT]...\n"
      "       [--align-by-arrival INPUT]... [--max-lag MS] [--allow-missing-topics]\n"
      "Replays the bag through this node's filter without a ROS master, in recorded-time\n"
      "order, and writes the estimates. Without --csv and --bag only a summary is printed.\n"
      "--frame-id, --child-frame-id: frames of the output bag's odometry (default odom,\n"
      "base_link, like the node's ~frame_id, ~child_frame_id); --base-frame: the frame\n"
      "FRAME_ALIGNED_INPUTS are rotated into (default BASE_FRAME, like ~base_frame), with\n"
      "the bag's /tf_static and /tf. --allow-missing-topics: a configured topic missing from\n"
      "the bag is a warning (its inputs are missing in every period), not an error.\n"
      "POLICY: AVERAGE, LAST, SAMPLED, 'HOLD LAGRANGE|BEZIER|TAYLOR ORDER [VARIANCE]' or\n"
      "'FILL OMEGA N [VARIANCE]'; THRESHOLD 0 removes a gate (doc/alignment_policies.md).";
  sf_filter::ReplayOptions options;
  options.nodeName = program.substr(program.find_last_of('/') + 1);
  double periodMs = sf_config::kEstimationPeriodMs, scaleQ = 1.0, scaleR = 1.0;
  double lagMs = sf_config::kMaxMeasurementLagMs;
  std::optional<long> seed;
  std::string baseFrame(sf_config::kBaseFrame);
  std::vector<sf_filter::InputOptions> inputs = sf_config::defaultInputOptions();
  const sf_filter::InputCapabilities can = inputCapabilities();
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw std::invalid_argument("option " + arg + " needs a value");
        return argv[++i];
      };
      if (arg == "--help") {
        std::cout << usage << std::endl;
        return EXIT_SUCCESS;
      } else if (arg == "--replay") {
        options.inputBag = value();
      } else if (arg == "--csv") {
        options.csvPath = value();
      } else if (arg == "--bag") {
        options.outputBag = value();
      } else if (arg == "--name") {
        options.nodeName = value();
      } else if (arg == "--estimation-period") {
        periodMs = std::stod(value());
      } else if (arg == "--scale-q") {
        scaleQ = std::stod(value());
      } else if (arg == "--scale-r") {
        scaleR = std::stod(value());
      } else if (arg == "--seed") {
        seed = std::stol(value());
      } else if (arg == "--frame-id") {
        options.frameId = value();
      } else if (arg == "--child-frame-id") {
        options.childFrameId = value();
      } else if (arg == "--base-frame") {
        baseFrame = value();
      } else if (arg == "--align" || arg == "--gate") {
        const std::string given = value();
        const std::size_t equals = given.find('=');
        if (equals == std::string::npos) {
          throw std::invalid_argument(arg + " " + given + ": expected INPUT=" +
                                      (arg == "--align" ? "POLICY" : "THRESHOLD"));
        }
        try {
          const long input = inputIndex(given.substr(0, equals));
          if (arg == "--align") {
            sf_filter::overrideAlignment(inputs, input, given.substr(equals + 1), can);
          } else {
            sf_filter::overrideGate(inputs, input, std::stod(given.substr(equals + 1)), can);
          }
        } catch (const std::logic_error& e) {  // invalid_argument and stod's out_of_range
          throw std::invalid_argument(arg + " " + given + ": " + e.what());
        }
      } else if (arg == "--align-by-stamp" || arg == "--align-by-arrival") {
        const std::string given = value();
        try {
          sf_filter::overrideAlignByStamp(inputs, inputIndex(given), arg == "--align-by-stamp",
                                          can);
        } catch (const std::invalid_argument& e) {
          throw std::invalid_argument(arg + " " + given + ": " + e.what());
        }
      } else if (arg == "--allow-missing-topics") {
        options.allowMissingTopics = true;
      } else if (arg == "--max-lag") {
        lagMs = sf_filter::checkedLagMs(std::stod(value()));
      } else {
        throw std::invalid_argument("unknown option " + arg);
      }
    }
    if (!(periodMs > 0.0)) throw std::invalid_argument("--estimation-period must be positive");
    if (!(scaleQ > 0.0) || !(scaleR > 0.0))
      throw std::invalid_argument("scale factors must be positive");
    if (seed && *seed < 0) throw std::invalid_argument("--seed must not be negative");
    if (sf_config::kHasFrameAlignment && (baseFrame.empty() || baseFrame.front() == '/')) {
      throw std::invalid_argument("--base-frame '" + baseFrame +
                                  "' is not a tf2 frame name (not empty, no leading '/')");
    }
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n" << usage << std::endl;
    return 2;
  }
  // In a child process: a library crashing on a corrupt bag, or an interrupt, still ends
  // with one line and without partial outputs (contained_run.hpp).
  auto replayBag = [&]() -> int {
    static sf_filter::ReplayLibraryMessages libraryMessages(program);
    console_bridge::useOutputHandler(&libraryMessages);
    try {
      ros::Time::init();
      sf_config::Parameters parameters = sf_config::defaultParameters(periodMs);
      parameters.process_noise_covariance *= scaleQ;
      parameters.measurement_noise_covariance *= scaleR;
      if (seed) parameters.random_seed = static_cast<unsigned>(*seed);
      std::optional<sf_filter::ReplayFrameAligner> aligner;
      if constexpr (sf_config::kHasFrameAlignment) aligner.emplace(baseFrame, inputNames());
      sf_filter::ReplayFrameAligner* const alignerPtr = aligner ? &*aligner : nullptr;
      sf_filter::BagReplay<sf_filter::generated::Filter> replay(
          sf_filter::generated::makeFilter(parameters), coreOptions(periodMs, inputs, lagMs),
          describe(alignerPtr), options);
      if (aligner) {
        replay.readTransforms([alignerPtr](const tf2_msgs::TFMessage& msg, bool isStatic) {
          alignerPtr->addTransforms(msg, isStatic);
        });
      }
      subscribeInputs(replay, alignerPtr);
      const auto start = std::chrono::steady_clock::now();
      const sf_filter::ReplaySummary s = replay.run();
      const double wall =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::uint64_t gated = 0, late = 0, substituted = 0;
      for (sf_filter::Index i = 0; i < replay.core().inputCount(); ++i) {
        gated += replay.core().counters(i).gated;
        late += replay.core().counters(i).late;
        substituted += replay.core().counters(i).substituted;
      }
      std::cout << options.nodeName << ": " << s.messages << " messages, " << s.estimates
                << " estimates, " << s.dropped << " dropped values (" << late << " late), " << gated
                << " gated, " << substituted << " substitutes, "
                << (s.estimates ? 1e6 * s.estimatorSeconds / static_cast<double>(s.estimates) : 0.0)
                << " us per estimation step, " << wall << " s in all" << std::endl;
      printInputCounters(options.nodeName, replay.core());
      if (aligner) {
        std::cout << options.nodeName << ": " << aligner->transforms()
                  << " transforms read from the bag's /tf_static and /tf ("
                  << aligner->rejectedTransforms() << " refused by tf2), "
                  << aligner->droppedTotal() << " values dropped: not rotatable into '"
                  << aligner->baseFrame() << "'" << std::endl;
      }
    } catch (const std::exception& e) {
      std::cerr << program << ": " << e.what() << std::endl;
      return EXIT_FAILURE;
    }
    return EXIT_SUCCESS;
  };
  return sf_filter::runContained(replayBag, [&](int signal) {
    for (const std::string& path : {options.csvPath, options.outputBag}) {
      if (!path.empty()) std::remove(sf_filter::partialPath(path).c_str());
    }
    if (signal == SIGINT || signal == SIGTERM || signal == SIGHUP) {
      std::cerr << program << ": interrupted (" << strsignal(signal) << "), no output written"
                << std::endl;
    } else {
      std::cerr << program << ": reading bag " << options.inputBag << " crashed the bag library ("
                << strsignal(signal) << "): the bag is corrupt; no output written" << std::endl;
    }
  });
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--replay" || std::string(argv[i]) == "--help") {
      return replayMain(argc, argv);
    }
  }
  ros::init(argc, argv, "sf_filter");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  std::optional<sf_filter::FrameAligner> aligner;  // outlives the node's subscriptions
  std::optional<Node> node;
  try {
    if constexpr (sf_config::kHasFrameAlignment) {
      aligner.emplace(pnh, std::string(sf_config::kBaseFrame), inputNames());
    }
    const auto parameters = sf_filter::loadParameters<sf_config::Parameters>(
        pnh, [](double periodMs) { return sf_config::defaultParameters(periodMs); },
        sf_config::kEstimationPeriodMs);
    std::vector<sf_filter::InputOptions> inputs = sf_config::defaultInputOptions();
    double lagMs = sf_config::kMaxMeasurementLagMs;
    sf_filter::loadInputParameters(pnh, inputs, lagMs, inputCapabilities());
    const sf_filter::FaultSettings faults =
        sf_filter::loadFaultParameters(pnh, inputs, inputCapabilities());
    auto options =
        coreOptions(parameters.estimation_period_ms, inputs, lagMs, faults.maxFutureStampMs);
    options.nisWindow = static_cast<std::size_t>(faults.nisWindow);
    node.emplace(nh, pnh, sf_filter::generated::makeFilter(parameters), options,
                 describe(aligner ? &*aligner : nullptr), faults.diagnosticPeriod);
  } catch (const std::exception& e) {
    ROS_FATAL("%s: refusing to start: %s", ros::this_node::getName().c_str(), e.what());
    return EXIT_FAILURE;
  }
  subscribeInputs(*node, aligner ? &*aligner : nullptr);
  node->start();
  ros::spin();
  // On stdout: ros::shutdown() has ended rosconsole, so ROS_INFO would print nothing now.
  std::cout << ros::this_node::getName() << ": " << inputCountersLine(node->core(), inputNames())
            << std::endl;
  return EXIT_SUCCESS;
}

#endif  // SF_CONFIG_OK
