# Sourced by the DDS interop scripts: Cyclone on the loopback interface only, unicast discovery to
# 127.0.0.1 (as tests/support's dds_loopback.hpp and docs/ros2.md have it), and a DDS domain of
# this test's own, so that tests running at once never meet.
export CYCLONEDDS_URI='<CycloneDDS><Domain id="any"><General><Interfaces><NetworkInterface name="lo"/></Interfaces><AllowMulticast>false</AllowMulticast></General><Discovery><ParticipantIndex>auto</ParticipantIndex><MaxAutoParticipantIndex>20</MaxAutoParticipantIndex><Peers><Peer address="127.0.0.1"/></Peers></Discovery></Domain></CycloneDDS>'
export DDS_DOMAIN=$(( $$ % 200 + 1 ))
