// The floor of the recording benchmark (measure_recording_cpu.sh, doc/node_benchmarks.md): a
// node that subscribes to the topics given as arguments the way the fusion node does (as
// serialized messages, topic_tools::ShapeShifter, queue 1000) and does nothing with them. Its
// CPU time is what roscpp alone costs for the traffic; the fusion node's above it is its own.
// Prints the number of messages it received when it ends.
#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

#include <ros/ros.h>
#include <topic_tools/shape_shifter.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "sf_subscribe_floor");
  if (argc < 2) {
    std::cerr << "usage: sf_subscribe_floor_node TOPIC... [__name:=NAME]" << std::endl;
    return 1;
  }
  ros::NodeHandle nh;
  std::uint64_t received = 0;
  std::vector<ros::Subscriber> subscribers;
  for (int i = 1; i < argc; ++i) {
    subscribers.push_back(nh.subscribe<topic_tools::ShapeShifter>(
        argv[i], 1000, [&received](const topic_tools::ShapeShifter::ConstPtr&) { ++received; }));
  }
  ros::spin();
  std::cout << ros::this_node::getName() << ": " << received << " messages received" << std::endl;
  return 0;
}
