/* A DDS subscriber made only of Cyclone's C API and the types idlc compiled from
 * ros2_messages.idl: it reads kestrel's topics as any DDS application (or ROS 2 node) would, and
 * prints the first message of each as JSON, for check_dds_idl.sh to compare with what kestrel
 * sent. Usage: idl_subscriber DOMAIN TIMEOUT_S PREFIX (topics PREFIX/frame/left, /cloud, /state,
 * /detections, /tracks, /truth). Exit 0 once each has arrived, 1 on timeout. */
#include <dds/dds.h>
#include <stdlib.h>
#include <string.h>

#include "idl_json.h"

typedef void (*print_fn)(FILE*, const void*);

struct wanted {
  const char* suffix;
  const dds_topic_descriptor_t* type;
  print_fn print;
  dds_entity_t reader;
  int received;
};

static void print_image(FILE* f, const void* m) { json_image(f, m); }
static void print_cloud(FILE* f, const void* m) { json_cloud(f, m); }
static void print_odometry(FILE* f, const void* m) { json_odometry(f, m); }
static void print_detections(FILE* f, const void* m) { json_detections(f, m); }
static void print_tracks(FILE* f, const void* m) { json_tracks(f, m); }
static void print_truth(FILE* f, const void* m) { json_truth(f, m); }

int main(int argc, char** argv) {
  if (argc != 4) {
    fprintf(stderr, "usage: idl_subscriber DOMAIN TIMEOUT_S PREFIX\n");
    return 2;
  }
  const dds_domainid_t domain = (dds_domainid_t)atoi(argv[1]);
  const double timeout_s = atof(argv[2]);
  const char* prefix = argv[3];
  struct wanted topics[] = {
      {"/frame/left", &sensor_msgs_msg_dds__Image__desc, print_image, 0, 0},
      {"/cloud", &sensor_msgs_msg_dds__PointCloud2__desc, print_cloud, 0, 0},
      {"/state", &nav_msgs_msg_dds__Odometry__desc, print_odometry, 0, 0},
      {"/detections", &kestrel_msgs_msg_dds__Detections__desc, print_detections, 0, 0},
      {"/tracks", &kestrel_msgs_msg_dds__Tracks__desc, print_tracks, 0, 0},
      {"/truth", &kestrel_msgs_msg_dds__GroundTruth__desc, print_truth, 0, 0},
  };
  const size_t n = sizeof topics / sizeof topics[0];
  const dds_entity_t participant = dds_create_participant(domain, NULL, NULL);
  if (participant < 0) {
    fprintf(stderr, "idl_subscriber: %s\n", dds_strretcode(participant));
    return 1;
  }
  /* ROS 2's default QoS: reliable, keep last 10, volatile. */
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
  dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 10);
  for (size_t i = 0; i < n; ++i) {
    char name[256];
    snprintf(name, sizeof name, "rt%s%s", prefix, topics[i].suffix);
    const dds_entity_t topic = dds_create_topic(participant, topics[i].type, name, NULL, NULL);
    topics[i].reader = dds_create_reader(participant, topic, qos, NULL);
    if (topic < 0 || topics[i].reader < 0) {
      fprintf(stderr, "idl_subscriber: cannot read %s\n", name);
      return 1;
    }
  }
  dds_delete_qos(qos);
  size_t done = 0;
  for (double waited = 0; done < n && waited < timeout_s; waited += 0.01) {
    for (size_t i = 0; i < n; ++i) {
      if (topics[i].received) continue;
      void* samples[1] = {NULL};
      dds_sample_info_t info[1];
      const dds_return_t got = dds_take(topics[i].reader, samples, info, 1, 1);
      if (got > 0 && info[0].valid_data) {
        printf("{\"topic\":\"%s%s\",\"message\":", prefix, topics[i].suffix);
        topics[i].print(stdout, samples[0]);
        printf("}\n");
        fflush(stdout);
        topics[i].received = 1;
        ++done;
      }
      if (got > 0) dds_return_loan(topics[i].reader, samples, got);
    }
    dds_sleepfor(DDS_MSECS(10));
  }
  for (size_t i = 0; i < n; ++i)
    if (!topics[i].received) fprintf(stderr, "idl_subscriber: nothing arrived on %s%s\n", prefix, topics[i].suffix);
  dds_delete(participant);
  return done == n ? 0 : 1;
}
