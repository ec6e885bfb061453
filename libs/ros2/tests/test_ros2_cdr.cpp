// CDR encoding, ros2msg schemas and the generic decoder, on bytes whose layout is known.
#include <gmock/gmock.h>

#include "kestrel/ros2/cdr.hpp"
#include "kestrel/ros2/cdr_json.hpp"
#include "kestrel/ros2/ros2msg.hpp"

using namespace kestrel::ros2;

namespace {

// sensor_msgs/msg/Image as rosbag2 stores its schema: the .msg text (comments and all), then each
// dependency after a separator line.
const char* const kImageSchema = R"(# This message contains an uncompressed image
std_msgs/Header header # Header timestamp should be acquisition time of image
uint32 height                # image height, that is, number of rows
uint32 width                 # image width, that is, number of columns
string encoding       # Encoding of pixels
uint8 is_bigendian    # is this data bigendian?
uint32 step           # Full row length in bytes
uint8[] data          # actual matrix data, size is (step * rows)

================================================================================
MSG: std_msgs/Header
# Standard metadata for higher-level stamped data types.
builtin_interfaces/Time stamp
string frame_id

================================================================================
MSG: builtin_interfaces/Time
int32 sec
uint32 nanosec
)";

}  // namespace

TEST(Cdr, LaysOutPrimitivesAlignedFromTheEndOfTheHeader) {
  CdrWriter w;
  w.u8(1);
  w.u32(2);
  w.string("hi");
  w.f64(1.5);
  const std::vector<std::uint8_t> expected = {0x00, 0x01, 0x00, 0x00,                           // CDR_LE
                                              0x01, 0x00, 0x00, 0x00,                           // u8, then padding to 4
                                              0x02, 0x00, 0x00, 0x00,                           // u32
                                              0x03, 0x00, 0x00, 0x00, 'h',  'i',  0x00,         // length counts the NUL
                                              0x00,                                             // padding to 8
                                              0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF8, 0x3F};  // 1.5
  EXPECT_EQ(w.data(), expected);

  CdrReader r(w.data());
  EXPECT_EQ(r.u8(), 1);
  EXPECT_EQ(r.u32(), 2u);
  EXPECT_EQ(r.string(), "hi");
  EXPECT_EQ(r.f64(), 1.5);
  EXPECT_EQ(r.remaining(), 0u);
}

TEST(Cdr, AStdMsgsStringIsTheBytesRos2Writes) {
  CdrWriter w;
  w.string("hello");
  const std::vector<std::uint8_t> ros2 = {0x00, 0x01, 0x00, 0x00, 0x06, 0x00, 0x00,
                                          0x00, 'h',  'e',  'l',  'l',  'o',  0x00};
  EXPECT_EQ(w.data(), ros2);
  const MessageSchema schema("std_msgs/msg/String", "string data\n");
  EXPECT_EQ(cdr_to_json(schema, ros2).dump(), R"({"data":"hello"})");
}

TEST(Cdr, BadBytesAreRefusedNotOverread) {
  EXPECT_THROW(CdrReader(std::vector<std::uint8_t>{0x00}), CdrError);
  EXPECT_THROW(CdrReader(std::vector<std::uint8_t>{0x00, 0x00, 0x00, 0x00}), CdrError);  // big-endian CDR
  CdrWriter w;
  w.u32(1000);  // a sequence of 1000 bytes with none after it
  CdrReader r(w.data());
  EXPECT_THROW(r.bytes(), CdrError);
  CdrReader short_read(std::vector<std::uint8_t>{0x00, 0x01, 0x00, 0x00, 0x01, 0x02});
  EXPECT_THROW(short_read.u32(), CdrError);
}

TEST(Ros2Msg, ReadsASchemaWithItsDependenciesAsRosbag2WritesIt) {
  const MessageSchema schema("sensor_msgs/msg/Image", kImageSchema);
  const MessageDefinition& image = schema.root();
  EXPECT_EQ(image.name, "sensor_msgs/Image");
  ASSERT_EQ(image.fields.size(), 7u);
  EXPECT_EQ(image.fields[0].name, "header");
  EXPECT_TRUE(image.fields[0].type.is_message);
  EXPECT_EQ(image.fields[0].type.name, "std_msgs/Header");
  EXPECT_EQ(image.fields[6].name, "data");
  EXPECT_EQ(image.fields[6].type.array, FieldType::Array::sequence);
  EXPECT_EQ(schema.definition("builtin_interfaces/msg/Time").fields.size(), 2u);
}

TEST(Ros2Msg, ConstantsDefaultsArraysAndBoundsAreRead) {
  const MessageSchema schema("pkg/msg/Sample", R"(
uint8 MODE_A=1   # a constant, not serialized
string NAME="x # not a comment"
float64[9] k
int32[<=3] bounded
string<=10 short_text
int32 with_default 7
Point[] points        # a type of the same package
===
MSG: pkg/Point
float64 x
float64 y
)");
  const MessageDefinition& def = schema.root();
  ASSERT_EQ(def.constants.size(), 2u);
  EXPECT_EQ(def.constants[0].name, "MODE_A");
  EXPECT_EQ(def.constants[1].value, "\"x # not a comment\"");
  ASSERT_EQ(def.fields.size(), 5u);
  EXPECT_EQ(def.fields[0].type.array, FieldType::Array::fixed);
  EXPECT_EQ(def.fields[0].type.length, 9u);
  EXPECT_EQ(def.fields[1].type.length, 3u);
  EXPECT_EQ(def.fields[2].type.name, "string");
  EXPECT_EQ(def.fields[3].name, "with_default");
  EXPECT_EQ(def.fields[4].type.name, "pkg/Point");
}

TEST(Ros2Msg, ErrorsNameTheSchemaAndTheLine) {
  try {
    MessageSchema("pkg/msg/Bad", "float64 x\nfloat64[abc] y\n");
    FAIL();
  } catch (const SchemaError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("line 2"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("abc"));
  }
  EXPECT_THROW(MessageSchema("pkg/msg/Bad", "geometry_msgs/Point p\n"), SchemaError);  // not defined
  EXPECT_THROW(MessageSchema("pkg/msg/Bad", "float64\n"), SchemaError);
  EXPECT_THROW(MessageSchema("NoPackage", "float64 x\n"), SchemaError);
}

TEST(CdrJson, DecodesAnImageByItsSchemaAlone) {
  CdrWriter w;
  w.i32(12);          // header.stamp.sec
  w.u32(500);         // header.stamp.nanosec
  w.string("left");   // header.frame_id
  w.u32(2);           // height
  w.u32(3);           // width
  w.string("mono8");  // encoding
  w.u8(0);            // is_bigendian
  w.u32(3);           // step
  const std::vector<std::uint8_t> pixels = {1, 2, 3, 4, 5, 255};
  w.bytes(pixels);
  const MessageSchema schema("sensor_msgs/msg/Image", kImageSchema);
  EXPECT_EQ(cdr_to_json(schema, w.data()).dump(),
            R"({"header":{"stamp":{"sec":12,"nanosec":500},"frame_id":"left"},"height":2,"width":3,)"
            R"("encoding":"mono8","is_bigendian":0,"step":3,"data":[1,2,3,4,5,255]})");
}

TEST(CdrJson, FixedArraysNestedSequencesAndEmptyMessages) {
  const MessageSchema schema("pkg/msg/Sample", R"(float64[2] k
Point[] points
Empty nothing
int64 big
===
MSG: pkg/Point
float32 x
uint16 y
===
MSG: pkg/Empty
)");
  CdrWriter w;
  w.f64(0.5);
  w.f64(-2.0);
  w.sequence_length(2);
  w.f32(1.0f);
  w.u16(7);
  w.f32(std::numeric_limits<float>::quiet_NaN());  // NaN has no JSON number: null
  w.u16(8);
  w.u8(0);                        // the empty message's one byte
  w.i64(-9'007'199'254'740'993);  // beyond a double's exact integers
  EXPECT_EQ(cdr_to_json(schema, w.data()).dump(),
            R"({"k":[0.5,-2.0],"points":[{"x":1.0,"y":7},{"x":null,"y":8}],"nothing":{},"big":-9007199254740993})");
  std::vector<std::uint8_t> longer = w.data();
  longer.insert(longer.end(), 8, 0);
  EXPECT_THROW(cdr_to_json(schema, longer), CdrError);  // bytes of something else after the message
  std::vector<std::uint8_t> shorter(w.data().begin(), w.data().end() - 3);
  EXPECT_THROW(cdr_to_json(schema, shorter), CdrError);
}
