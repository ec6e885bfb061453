#include "raw_cdr_type.hpp"

#include <dds/ddsi/q_radmin.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace kestrel::dds::detail {
namespace {

struct RawSertype : ddsi_sertype {};

RawSerdata* new_serdata(const ddsi_sertype* type, ddsi_serdata_kind kind, std::size_t size) {
  auto* d = new RawSerdata;
  ddsi_serdata_init(d, type, kind);
  // Keyless: every sample is the same instance, so the hash is the type's.
  d->hash = type->serdata_basehash;
  if (kind == SDK_DATA) d->bytes.resize(size);
  return d;
}

// --- serdata: one sample's bytes ---

bool eqkey(const ddsi_serdata*, const ddsi_serdata*) { return true; }

uint32_t get_size(const ddsi_serdata* d) {
  return static_cast<uint32_t>(static_cast<const RawSerdata*>(d)->bytes.size());
}

ddsi_serdata* from_ser(const ddsi_sertype* type, ddsi_serdata_kind kind, const nn_rdata* fragchain, size_t size) {
  auto* d = new_serdata(type, kind, size);
  if (kind != SDK_DATA) return d;
  // The fragments may overlap; each adds the bytes past what the ones before it gave.
  uint32_t off = 0;
  for (const nn_rdata* fg = fragchain; fg != nullptr; fg = fg->nextfrag) {
    if (fg->maxp1 <= off) continue;
    const auto* payload = NN_RMSG_PAYLOADOFF(fg->rmsg, NN_RDATA_PAYLOAD_OFF(fg));
    const std::size_t end = std::min<std::size_t>(fg->maxp1, size);
    if (end > off) std::memcpy(d->bytes.data() + off, payload + (off - fg->min), end - off);
    off = fg->maxp1;
  }
  return d;
}

ddsi_serdata* from_ser_iov(const ddsi_sertype* type, ddsi_serdata_kind kind, ddsrt_msg_iovlen_t niov,
                           const ddsrt_iovec_t* iov, size_t size) {
  auto* d = new_serdata(type, kind, size);
  if (kind != SDK_DATA) return d;
  std::size_t off = 0;
  for (ddsrt_msg_iovlen_t i = 0; i < niov && off < size; ++i) {
    const std::size_t n = std::min<std::size_t>(iov[i].iov_len, size - off);
    std::memcpy(d->bytes.data() + off, iov[i].iov_base, n);
    off += n;
  }
  return d;
}

ddsi_serdata* from_keyhash(const ddsi_sertype* type, const ddsi_keyhash*) { return new_serdata(type, SDK_KEY, 0); }

ddsi_serdata* from_sample(const ddsi_sertype* type, ddsi_serdata_kind kind, const void* sample) {
  const auto* raw = static_cast<const RawSample*>(sample);
  auto* d = new_serdata(type, kind, kind == SDK_DATA ? raw->size : 0);
  if (kind == SDK_DATA && raw->size > 0) std::memcpy(d->bytes.data(), raw->data, raw->size);
  return d;
}

void to_ser(const ddsi_serdata* d, size_t off, size_t sz, void* buf) {
  const auto& bytes = static_cast<const RawSerdata*>(d)->bytes;
  if (off < bytes.size()) std::memcpy(buf, bytes.data() + off, std::min(sz, bytes.size() - off));
}

ddsi_serdata* to_ser_ref(const ddsi_serdata* d, size_t off, size_t sz, ddsrt_iovec_t* ref) {
  const auto& bytes = static_cast<const RawSerdata*>(d)->bytes;
  ref->iov_base = const_cast<std::uint8_t*>(bytes.data()) + off;
  ref->iov_len = static_cast<ddsrt_iov_len_t>(std::min(sz, bytes.size() - std::min(off, bytes.size())));
  return ddsi_serdata_ref(d);
}

void to_ser_unref(ddsi_serdata* d, const ddsrt_iovec_t*) { ddsi_serdata_unref(d); }

// A sample read with dds_read()/dds_take() is a std::vector<uint8_t> receiving a copy.
bool to_sample(const ddsi_serdata* d, void* sample, void**, void*) {
  if (d->kind != SDK_DATA) return true;
  *static_cast<std::vector<std::uint8_t>*>(sample) = static_cast<const RawSerdata*>(d)->bytes;
  return true;
}

ddsi_serdata* to_untyped(const ddsi_serdata* d) {
  auto* key = new_serdata(d->type, SDK_KEY, 0);
  key->type = nullptr;
  return key;
}

bool untyped_to_sample(const ddsi_sertype*, const ddsi_serdata*, void*, void**, void*) { return true; }

void free_serdata(ddsi_serdata* d) { delete static_cast<RawSerdata*>(d); }

size_t print(const ddsi_sertype*, const ddsi_serdata* d, char* buf, size_t size) {
  const int n = std::snprintf(buf, size, "%zu bytes of CDR", static_cast<const RawSerdata*>(d)->bytes.size());
  return n < 0 ? 0 : static_cast<size_t>(n);
}

void get_keyhash(const ddsi_serdata*, ddsi_keyhash* buf, bool) { std::memset(buf, 0, sizeof(*buf)); }

const ddsi_serdata_ops kSerdataOps = {
    eqkey,        get_size,  from_ser,   from_ser_iov,      from_keyhash, from_sample, to_ser,      to_ser_ref,
    to_ser_unref, to_sample, to_untyped, untyped_to_sample, free_serdata, print,       get_keyhash,
#ifdef DDS_HAS_SHM
    nullptr,      nullptr,
#endif
};

// --- sertype: the type itself ---

void free_sertype(ddsi_sertype* tp) {
  ddsi_sertype_fini(tp);
  delete static_cast<RawSertype*>(tp);
}

void zero_samples(const ddsi_sertype*, void* samples, size_t count) {
  auto* v = static_cast<std::vector<std::uint8_t>*>(samples);
  for (size_t i = 0; i < count; ++i) v[i].clear();
}

void realloc_samples(void** ptrs, const ddsi_sertype*, void* old, size_t oldcount, size_t count) {
  auto* fresh = new std::vector<std::uint8_t>[count];
  auto* before = static_cast<std::vector<std::uint8_t>*>(old);
  for (size_t i = 0; i < std::min(oldcount, count); ++i) fresh[i] = std::move(before[i]);
  delete[] before;
  for (size_t i = 0; i < count; ++i) ptrs[i] = &fresh[i];
}

void free_samples(const ddsi_sertype*, void** ptrs, size_t count, dds_free_op_t op) {
  if (count == 0) return;
  auto* first = static_cast<std::vector<std::uint8_t>*>(ptrs[0]);
  if (op & DDS_FREE_ALL_BIT) {
    delete[] first;
  } else {
    for (size_t i = 0; i < count; ++i) static_cast<std::vector<std::uint8_t>*>(ptrs[i])->clear();
  }
}

// Two sertypes of these operations are the same type when their names are (Cyclone compares
// names and operations before asking).
bool equal(const ddsi_sertype*, const ddsi_sertype*) { return true; }
uint32_t hash(const ddsi_sertype*) { return 0; }

size_t serialized_size(const ddsi_sertype*, const void* sample) { return static_cast<const RawSample*>(sample)->size; }

bool serialize_into(const ddsi_sertype*, const void* sample, void* dst, size_t size) {
  const auto* raw = static_cast<const RawSample*>(sample);
  if (size < raw->size) return false;
  std::memcpy(dst, raw->data, raw->size);
  return true;
}

const ddsi_sertype_ops kSertypeOps = {
    ddsi_sertype_v0,
    nullptr,
    free_sertype,
    zero_samples,
    realloc_samples,
    free_samples,
    equal,
    hash,
    // No XTypes type information: peers match on the type name, as ROS 2 Humble's do.
    nullptr,
    nullptr,
    nullptr,
    nullptr,
    serialized_size,
    serialize_into,
};

}  // namespace

ddsi_sertype* make_raw_cdr_sertype(const std::string& dds_type_name) {
  auto* st = new RawSertype;
  std::memset(static_cast<ddsi_sertype*>(st), 0, sizeof(ddsi_sertype));
  ddsi_sertype_init_flags(st, dds_type_name.c_str(), &kSertypeOps, &kSerdataOps, DDSI_SERTYPE_FLAG_TOPICKIND_NO_KEY);
  st->allowed_data_representation = DDS_DATA_REPRESENTATION_FLAG_XCDR1;
  return st;
}

}  // namespace kestrel::dds::detail
