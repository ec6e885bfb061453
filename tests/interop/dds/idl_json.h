/* The interop test's own view of the messages: each idlc-generated struct printed as the JSON that
 * ROS 2's field names give (as `kestrel mcap cat` and `kestrel dds echo` print them), so that a
 * script compares what this independent decoder read with what kestrel sent, field by field. */
#ifndef KESTREL_INTEROP_IDL_JSON_H
#define KESTREL_INTEROP_IDL_JSON_H

#include <stdio.h>

#include "ros2_messages.h"

static void json_double(FILE* out, double v) { fprintf(out, "%.17g", v); }

static void json_string(FILE* out, const char* s) {
  fputc('"', out);
  for (; s != NULL && *s != '\0'; ++s) {
    if (*s == '"' || *s == '\\') fputc('\\', out);
    fputc(*s, out);
  }
  fputc('"', out);
}

static void json_header(FILE* out, const std_msgs_msg_dds__Header_* h) {
  fprintf(out, "{\"stamp\":{\"sec\":%d,\"nanosec\":%u},\"frame_id\":", h->stamp.sec, h->stamp.nanosec);
  json_string(out, h->frame_id);
  fputc('}', out);
}

static void json_xyz(FILE* out, double x, double y, double z) {
  fputs("{\"x\":", out);
  json_double(out, x);
  fputs(",\"y\":", out);
  json_double(out, y);
  fputs(",\"z\":", out);
  json_double(out, z);
  fputc('}', out);
}

static void json_doubles(FILE* out, const double* v, unsigned n) {
  fputc('[', out);
  for (unsigned i = 0; i < n; ++i) {
    if (i > 0) fputc(',', out);
    json_double(out, v[i]);
  }
  fputc(']', out);
}

static void json_octets(FILE* out, const unsigned char* v, unsigned n) {
  fputc('[', out);
  for (unsigned i = 0; i < n; ++i) fprintf(out, i > 0 ? ",%u" : "%u", v[i]);
  fputc(']', out);
}

static void json_odometry(FILE* out, const nav_msgs_msg_dds__Odometry_* m) {
  const geometry_msgs_msg_dds__Pose_* p = &m->pose.pose;
  const geometry_msgs_msg_dds__Twist_* t = &m->twist.twist;
  fputs("{\"header\":", out);
  json_header(out, &m->header);
  fputs(",\"child_frame_id\":", out);
  json_string(out, m->child_frame_id);
  fputs(",\"pose\":{\"pose\":{\"position\":", out);
  json_xyz(out, p->position.x, p->position.y, p->position.z);
  fputs(",\"orientation\":{\"x\":", out);
  json_double(out, p->orientation.x);
  fputs(",\"y\":", out);
  json_double(out, p->orientation.y);
  fputs(",\"z\":", out);
  json_double(out, p->orientation.z);
  fputs(",\"w\":", out);
  json_double(out, p->orientation.w);
  fputs("}},\"covariance\":", out);
  json_doubles(out, m->pose.covariance, 36);
  fputs("},\"twist\":{\"twist\":{\"linear\":", out);
  json_xyz(out, t->linear.x, t->linear.y, t->linear.z);
  fputs(",\"angular\":", out);
  json_xyz(out, t->angular.x, t->angular.y, t->angular.z);
  fputs("},\"covariance\":", out);
  json_doubles(out, m->twist.covariance, 36);
  fputs("}}", out);
}

static void json_image(FILE* out, const sensor_msgs_msg_dds__Image_* m) {
  fputs("{\"header\":", out);
  json_header(out, &m->header);
  fprintf(out, ",\"height\":%u,\"width\":%u,\"encoding\":", m->height, m->width);
  json_string(out, m->encoding);
  fprintf(out, ",\"is_bigendian\":%u,\"step\":%u,\"data\":", m->is_bigendian, m->step);
  json_octets(out, m->data._buffer, m->data._length);
  fputc('}', out);
}

static void json_cloud(FILE* out, const sensor_msgs_msg_dds__PointCloud2_* m) {
  fputs("{\"header\":", out);
  json_header(out, &m->header);
  fprintf(out, ",\"height\":%u,\"width\":%u,\"fields\":[", m->height, m->width);
  for (unsigned i = 0; i < m->fields._length; ++i) {
    const sensor_msgs_msg_dds__PointField_* f = &m->fields._buffer[i];
    fputs(i > 0 ? ",{\"name\":" : "{\"name\":", out);
    json_string(out, f->name);
    fprintf(out, ",\"offset\":%u,\"datatype\":%u,\"count\":%u}", f->offset, f->datatype, f->count);
  }
  fprintf(out, "],\"is_bigendian\":%s,\"point_step\":%u,\"row_step\":%u,\"data\":", m->is_bigendian ? "true" : "false",
          m->point_step, m->row_step);
  json_octets(out, m->data._buffer, m->data._length);
  fprintf(out, ",\"is_dense\":%s}", m->is_dense ? "true" : "false");
}

static void json_detections(FILE* out, const kestrel_msgs_msg_dds__Detections_* m) {
  fputs("{\"header\":", out);
  json_header(out, &m->header);
  fputs(",\"detections\":[", out);
  for (unsigned i = 0; i < m->detections._length; ++i) {
    const kestrel_msgs_msg_dds__Detection_* d = &m->detections._buffer[i];
    fputs(i > 0 ? ",{\"position\":" : "{\"position\":", out);
    json_xyz(out, d->position.x, d->position.y, d->position.z);
    fputs(",\"extent\":", out);
    json_xyz(out, d->extent.x, d->extent.y, d->extent.z);
    fprintf(out, ",\"point_count\":%d,\"confidence\":", d->point_count);
    json_double(out, d->confidence);
    fputc('}', out);
  }
  fputs("]}", out);
}

static void json_tracks(FILE* out, const kestrel_msgs_msg_dds__Tracks_* m) {
  fputs("{\"header\":", out);
  json_header(out, &m->header);
  fputs(",\"tracks\":[", out);
  for (unsigned i = 0; i < m->tracks._length; ++i) {
    const kestrel_msgs_msg_dds__Track_* t = &m->tracks._buffer[i];
    fprintf(out, "%s{\"id\":%llu,\"age\":%d,\"hits\":%d,\"misses\":%d,\"state\":", i > 0 ? "," : "",
            (unsigned long long)t->id, t->age, t->hits, t->misses);
    json_doubles(out, t->state._buffer, t->state._length);
    fputs(",\"covariance\":", out);
    json_doubles(out, t->covariance._buffer, t->covariance._length);
    fputs(",\"detection\":", out);
    json_xyz(out, t->detection.x, t->detection.y, t->detection.z);
    fputc('}', out);
  }
  fprintf(out, "],\"has_selected\":%s,\"selected_id\":%llu}", m->has_selected ? "true" : "false",
          (unsigned long long)m->selected_id);
}

static void json_truth(FILE* out, const kestrel_msgs_msg_dds__GroundTruth_* m) {
  fputs("{\"header\":", out);
  json_header(out, &m->header);
  fputs(",\"objects\":[", out);
  for (unsigned i = 0; i < m->objects._length; ++i) {
    const kestrel_msgs_msg_dds__GroundTruthObject_* o = &m->objects._buffer[i];
    fprintf(out, "%s{\"id\":%llu,\"position_world\":", i > 0 ? "," : "", (unsigned long long)o->id);
    json_xyz(out, o->position_world.x, o->position_world.y, o->position_world.z);
    fputs(",\"position_camera\":", out);
    json_xyz(out, o->position_camera.x, o->position_camera.y, o->position_camera.z);
    fputs(",\"velocity_world\":", out);
    json_xyz(out, o->velocity_world.x, o->velocity_world.y, o->velocity_world.z);
    fprintf(out, ",\"in_view\":%s}", o->in_view ? "true" : "false");
  }
  fputs("]}", out);
}

#endif
