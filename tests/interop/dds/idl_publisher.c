/* A DDS publisher made only of Cyclone's C API and the types idlc compiled from
 * ros2_messages.idl: it sends known messages on PREFIX/state (nav_msgs/Odometry),
 * PREFIX/detections, PREFIX/tracks and PREFIX/truth (kestrel_msgs) at 10 Hz, as a ROS 2 node would,
 * for kestrel's dds_bridge to read. The values are those dds_peer_tool's `expect` checks.
 * Usage: idl_publisher DOMAIN SECONDS PREFIX. */
#include <dds/dds.h>
#include <stdlib.h>
#include <string.h>

#include "ros2_messages.h"

static dds_entity_t writer(dds_entity_t participant, const dds_topic_descriptor_t* type, const char* prefix,
                           const char* suffix, const dds_qos_t* qos) {
  char name[256];
  snprintf(name, sizeof name, "rt%s%s", prefix, suffix);
  const dds_entity_t topic = dds_create_topic(participant, type, name, NULL, NULL);
  const dds_entity_t w = dds_create_writer(participant, topic, qos, NULL);
  if (topic < 0 || w < 0) {
    fprintf(stderr, "idl_publisher: cannot write %s\n", name);
    exit(1);
  }
  return w;
}

int main(int argc, char** argv) {
  if (argc != 4) {
    fprintf(stderr, "usage: idl_publisher DOMAIN SECONDS PREFIX\n");
    return 2;
  }
  const dds_domainid_t domain = (dds_domainid_t)atoi(argv[1]);
  const int ticks = (int)(atof(argv[2]) * 10);
  const char* prefix = argv[3];
  const dds_entity_t participant = dds_create_participant(domain, NULL, NULL);
  if (participant < 0) {
    fprintf(stderr, "idl_publisher: %s\n", dds_strretcode(participant));
    return 1;
  }
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
  dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 10);
  const dds_entity_t state_w = writer(participant, &nav_msgs_msg_dds__Odometry__desc, prefix, "/state", qos);
  const dds_entity_t detections_w = writer(participant, &kestrel_msgs_msg_dds__Detections__desc, prefix, "/detections", qos);
  const dds_entity_t tracks_w = writer(participant, &kestrel_msgs_msg_dds__Tracks__desc, prefix, "/tracks", qos);
  const dds_entity_t truth_w = writer(participant, &kestrel_msgs_msg_dds__GroundTruth__desc, prefix, "/truth", qos);
  dds_delete_qos(qos);

  nav_msgs_msg_dds__Odometry_ state;
  memset(&state, 0, sizeof state);
  state.header.stamp.sec = 12;
  state.header.stamp.nanosec = 345000000;
  state.header.frame_id = "world";
  state.child_frame_id = "hunter";
  state.pose.pose.position = (geometry_msgs_msg_dds__Point_){1.5, -2.0, 3.25};
  state.pose.pose.orientation = (geometry_msgs_msg_dds__Quaternion_){0.0, 0.0, 0.6, 0.8};
  /* The twist is in the body frame (ROS 2's child frame): yawed by 2 atan2(0.6, 0.8). */
  state.twist.twist.linear = (geometry_msgs_msg_dds__Vector3_){1.0, 0.5, -0.25};
  state.twist.twist.angular = (geometry_msgs_msg_dds__Vector3_){0.1, -0.2, 0.3};

  kestrel_msgs_msg_dds__Detection_ detection = {{0.25, -0.5, 6.0}, {0.4, 0.3, 0.2}, 42, 0.875};
  kestrel_msgs_msg_dds__Detections_ detections;
  memset(&detections, 0, sizeof detections);
  detections.header.stamp.sec = 12;
  detections.header.stamp.nanosec = 345000000;
  detections.header.frame_id = "camera";
  detections.detections._length = detections.detections._maximum = 1;
  detections.detections._buffer = &detection;

  double state_vector[6] = {1, 2, 3, 0.5, 0.25, 0.125};
  double covariance[36];
  for (int i = 0; i < 36; ++i) covariance[i] = (i % 7 == 0) ? 0.5 : 0.0;
  kestrel_msgs_msg_dds__Track_ track;
  memset(&track, 0, sizeof track);
  track.id = 9;
  track.age = 30;
  track.hits = 28;
  track.misses = 2;
  track.state._length = track.state._maximum = 6;
  track.state._buffer = state_vector;
  track.covariance._length = track.covariance._maximum = 36;
  track.covariance._buffer = covariance;
  track.detection = (geometry_msgs_msg_dds__Point_){0.25, -0.5, 6.0};
  kestrel_msgs_msg_dds__Tracks_ tracks;
  memset(&tracks, 0, sizeof tracks);
  tracks.header = detections.header;
  tracks.tracks._length = tracks.tracks._maximum = 1;
  tracks.tracks._buffer = &track;
  tracks.has_selected = true;
  tracks.selected_id = 9;

  kestrel_msgs_msg_dds__GroundTruthObject_ object = {4, {7.0, 0.5, 2.5}, {0.25, -0.5, 6.0}, {-1.0, 0.0, 0.5}, true};
  kestrel_msgs_msg_dds__GroundTruth_ truth;
  memset(&truth, 0, sizeof truth);
  truth.header = detections.header;
  truth.objects._length = truth.objects._maximum = 1;
  truth.objects._buffer = &object;

  for (int i = 0; i < ticks; ++i) {
    if (dds_write(state_w, &state) < 0 || dds_write(detections_w, &detections) < 0 ||
        dds_write(tracks_w, &tracks) < 0 || dds_write(truth_w, &truth) < 0) {
      fprintf(stderr, "idl_publisher: a write failed\n");
      return 1;
    }
    dds_sleepfor(DDS_MSECS(100));
  }
  dds_delete(participant);
  return 0;
}
