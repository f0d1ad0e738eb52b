#!/bin/sh
# make_rig_security.sh OUT_DIR RIG_ID...
#
# Makes, with openssl only and offline, what DDS Security (Cyclone's builtin auth,
# access-control and crypto plugins) needs for MHD's rigs (docs/networking.md,
# "Security"):
#   OUT_DIR/ca/ca_cert.pem, ca_key.pem      one CA, both identity CA and permissions CA
#   OUT_DIR/governance.xml                  the domain's rules (unsigned source)
#   OUT_DIR/identities/NAME/                one folder per process identity:
#       identity_ca.pem permissions_ca.pem  copies of the CA certificate
#       governance.p7s                      the governance, signed by the CA
#       cert.pem key.pem                    the identity (EC prime256v1), CN=NAME
#       permissions.xml permissions.p7s     what NAME may do, and the signed copy
# Identities: tracker-rigN and haptic-rigN for each RIG_ID N, viewer and ros2-viewer.
# Access control grants topics per partition, not per key: rig N's endpoints all live
# in partition "mhd_rigN" (libs/dds_common/rig_partition.h), so tracker-rigN may
# publish mhd_tracker_sample in mhd_rigN only. An identity folder is what a process
# names with MHD_DDS_IDENTITY, --dds-identity or a plugin's identity_dir parameter.
# Existing files under OUT_DIR are replaced. The CA key stays in OUT_DIR/ca: keep it
# off the rigs in real use.
set -eu

usage() {
  echo "usage: $0 OUT_DIR RIG_ID..." >&2
  exit 2
}
[ $# -ge 2 ] || usage
out=$1
shift
for rig in "$@"; do
  case $rig in
    '' | *[!0-9]*) echo "$0: rig id '$rig' is not a non-negative integer" >&2; exit 2 ;;
  esac
done
command -v openssl >/dev/null || { echo "$0: openssl not found" >&2; exit 1; }

# Domains 0..230: Cyclone's access-control parser refuses ids above 230 (the DDS
# Security limit), though MHD's plugins take 0..232 unsecured.
domain_min=0
domain_max=230
# Fixed validity, so that the same inputs give the same documents.
not_before=2020-01-01T00:00:00
not_after=2120-01-01T00:00:00
cert_days=36500
subject_org=MHD

mkdir -p "$out/ca" "$out/identities"
ca_cert=$out/ca/ca_cert.pem
ca_key=$out/ca/ca_key.pem

quiet() { "$@" 2>"$out/.openssl.log" || { cat "$out/.openssl.log" >&2; exit 1; }; }

# The CA: EC prime256v1 (Cyclone's auth plugin takes RSA-2048 or P-256).
quiet openssl ecparam -name prime256v1 -genkey -noout -out "$ca_key"
chmod 600 "$ca_key"
quiet openssl req -x509 -new -key "$ca_key" -sha256 -days "$cert_days" -subj "/O=$subject_org/CN=MHD rig CA" \
  -out "$ca_cert"

sign() {  # sign IN OUT: S/MIME, signer certificate included, as Cyclone's AC plugin reads
  quiet openssl smime -sign -in "$1" -text -out "$2" -signer "$ca_cert" -inkey "$ca_key"
}

# Governance: only authenticated participants join, discovery and liveliness are
# encrypted, and every topic is under read and write access control with its
# payload encrypted and its submessages signed (so no one can forge sequence numbers).
cat >"$out/governance.xml" <<EOF
<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_governance.xsd">
  <domain_access_rules>
    <domain_rule>
      <domains><id_range><min>$domain_min</min><max>$domain_max</max></id_range></domains>
      <allow_unauthenticated_participants>false</allow_unauthenticated_participants>
      <enable_join_access_control>true</enable_join_access_control>
      <discovery_protection_kind>ENCRYPT</discovery_protection_kind>
      <liveliness_protection_kind>ENCRYPT</liveliness_protection_kind>
      <rtps_protection_kind>NONE</rtps_protection_kind>
      <topic_access_rules>
        <topic_rule>
          <topic_expression>*</topic_expression>
          <enable_discovery_protection>true</enable_discovery_protection>
          <enable_liveliness_protection>true</enable_liveliness_protection>
          <enable_read_access_control>true</enable_read_access_control>
          <enable_write_access_control>true</enable_write_access_control>
          <metadata_protection_kind>SIGN</metadata_protection_kind>
          <data_protection_kind>ENCRYPT</data_protection_kind>
        </topic_rule>
      </topic_access_rules>
    </domain_rule>
  </domain_access_rules>
</dds>
EOF
sign "$out/governance.xml" "$out/governance.p7s"

# rule KIND PARTITION TOPIC...: one <publish> or <subscribe> element. PARTITION '':
# the default partition (no <partitions> element), where ROS 2 puts its topics.
rule() {
  kind=$1 partition=$2
  shift 2
  printf '        <%s>\n          <topics>\n' "$kind"
  for topic in "$@"; do printf '            <topic>%s</topic>\n' "$topic"; done
  printf '          </topics>\n'
  [ -z "$partition" ] || printf '          <partitions><partition>%s</partition></partitions>\n' "$partition"
  printf '        </%s>\n' "$kind"
}

# identity NAME RULES: key, certificate, permissions (RULES: the <publish>/<subscribe>
# elements) and the shared files, in OUT_DIR/identities/NAME.
identity() {
  name=$1 rules=$2
  dir=$out/identities/$name
  mkdir -p "$dir"
  quiet openssl ecparam -name prime256v1 -genkey -noout -out "$dir/key.pem"
  chmod 600 "$dir/key.pem"
  quiet openssl req -new -key "$dir/key.pem" -sha256 -subj "/O=$subject_org/CN=$name" -out "$dir/cert.csr"
  quiet openssl x509 -req -in "$dir/cert.csr" -CA "$ca_cert" -CAkey "$ca_key" -CAcreateserial \
    -CAserial "$out/ca/ca_cert.srl" -sha256 -days "$cert_days" -out "$dir/cert.pem"
  rm -f "$dir/cert.csr"
  cp "$ca_cert" "$dir/identity_ca.pem"
  cp "$ca_cert" "$dir/permissions_ca.pem"
  cp "$out/governance.p7s" "$dir/governance.p7s"
  cat >"$dir/permissions.xml" <<EOF
<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd">
  <permissions>
    <grant name="$name">
      <subject_name>CN=$name,O=$subject_org</subject_name>
      <validity><not_before>$not_before</not_before><not_after>$not_after</not_after></validity>
      <allow_rule>
        <domains><id_range><min>$domain_min</min><max>$domain_max</max></id_range></domains>
$rules      </allow_rule>
      <default>DENY</default>
    </grant>
  </permissions>
</dds>
EOF
  sign "$dir/permissions.xml" "$dir/permissions.p7s"
}

for rig in "$@"; do
  p=mhd_rig$rig
  # The tracker server publishes its rig's samples and nothing else; in simulation
  # (--shared-world) it reads the simulated world its rig's haptic server publishes.
  identity "tracker-rig$rig" "$(rule publish "$p" mhd_tracker_sample)
$(rule subscribe "$p" mhd_sim_world)
"
  # The haptic server reads its rig's samples and base commands, publishes its state,
  # in simulation (the dds tracker's publish_sim_world) its simulated world, and (the
  # ros2_state display) its ROS 2 topics, which live in the default partition. It claims
  # its rig id (mhd_rig_claim), reading the others' claims of it. It may read every
  # rig's tracker samples (the dds tracker's other_rigs: the others' users and bases), and
  # every rig's shared-object messages (the dds_link), but writes those as its rig only.
  identity "haptic-rig$rig" "$(rule subscribe "$p" mhd_tracker_sample mhd_base_command mhd_rig_claim)
$(rule subscribe 'mhd_rig*' mhd_tracker_sample mhd_shared_object)
$(rule publish "$p" mhd_rig_state mhd_rig_status mhd_sim_world mhd_rig_claim mhd_shared_object)
$(rule publish '' "rt/mhd/rig$rig/*")
"
done
# Viewers and the monitor read every rig and publish nothing.
identity viewer "$(rule subscribe 'mhd_rig*' mhd_tracker_sample mhd_rig_state mhd_rig_status mhd_base_command)
$(rule subscribe '' 'rt/mhd/rig*')
"
# A ROS 2 node (ros2 topic echo, rviz2) on rmw_cyclonedds: reads every rig's ROS 2
# topics and may use the topics every ROS 2 node has (its graph, rosout, parameter
# events, its parameter services), and nothing of MHD's own.
identity ros2-viewer "$(rule subscribe '' 'rt/mhd/rig*' ros_discovery_info rt/parameter_events 'rq/*' 'rr/*')
$(rule publish '' ros_discovery_info rt/rosout rt/parameter_events 'rq/*' 'rr/*')
"
rm -f "$out/.openssl.log" "$out/ca/ca_cert.srl"
echo "$0: CA, governance and identities for rig(s) $* in $out"
