#pragma once
// Device memory of the CUDA backend: DeviceArray, and the mirror of an array group
// (demState.hpp instantiated over DeviceArray) uploaded and downloaded field by field
// from the group's field list (demFields.hpp), so no array is named twice.
#include <cuda_runtime.h>

#include <cstddef>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "dem/demFields.hpp"

namespace rockfrac {
namespace {

constexpr int threads_per_block = 256;

void check(cudaError_t status, const char* what)
{
    if (status != cudaSuccess)
        throw UserError(
            std::string("CUDA backend: ") + what + " failed: " + cudaGetErrorString(status) +
            (status == cudaErrorMemoryAllocation ? " (the model does not fit in device memory)" : ""));
}

int blocksFor(int n)
{
    return (n + threads_per_block - 1) / threads_per_block;
}

// A device array of trivially copyable T: cudaMalloc'd, grown (never shrunk) on upload.
template <class T>
class DeviceArray {
public:
    DeviceArray() = default;
    ~DeviceArray() { cudaFree(data_); }
    DeviceArray(const DeviceArray&) = delete;
    DeviceArray& operator=(const DeviceArray&) = delete;

    // Size n; the contents are undefined when the array had to grow.
    void resize(std::size_t n)
    {
        if (n > capacity_) {
            cudaFree(data_);
            data_ = nullptr;
            capacity_ = 0;
            check(cudaMalloc(reinterpret_cast<void**>(&data_), n * sizeof(T)), "cudaMalloc");
            capacity_ = n;
        }
        size_ = n;
    }
    void upload(const std::vector<T>& v)
    {
        resize(v.size());
        if (!v.empty())
            check(cudaMemcpy(data_, v.data(), v.size() * sizeof(T), cudaMemcpyHostToDevice), "upload");
    }
    void download(std::vector<T>& v) const
    {
        v.resize(size_);
        if (size_ > 0)
            check(cudaMemcpy(v.data(), data_, size_ * sizeof(T), cudaMemcpyDeviceToHost), "download");
    }
    void copyFrom(const DeviceArray& other)
    {
        resize(other.size_);
        if (size_ > 0)
            check(cudaMemcpy(data_, other.data_, size_ * sizeof(T), cudaMemcpyDeviceToDevice), "device copy");
    }
    T* data() const { return data_; }
    std::size_t size() const { return size_; }
    std::size_t bytes() const { return capacity_ * sizeof(T); }

private:
    T* data_ = nullptr;
    std::size_t size_ = 0, capacity_ = 0;
};

// ---- One array, or one CSR pair, between host and device ----------------------------------

template <class T>
void upload(const std::vector<T>& host, DeviceArray<T>& device)
{
    device.upload(host);
}
template <class HO, class HV, class DO, class DV>
void upload(const Ranged<HO, HV>& host, const Ranged<DO, DV>& device)
{
    device.offset.upload(host.offset);
    device.values.upload(host.values);
}

template <class T>
void download(const DeviceArray<T>& device, std::vector<T>& host)
{
    device.download(host);
}

template <class T>
std::size_t deviceBytes(const DeviceArray<T>& a)
{
    return a.bytes();
}
template <class O, class V>
std::size_t deviceBytes(const Ranged<O, V>& r)
{
    return r.offset.bytes() + r.values.bytes();
}

// ---- A group's mirror -------------------------------------------------------------------
// Every array but the host-only ones and those with a flag in Without.

template <unsigned Without = 0u, class Host, class Device>
void uploadFields(const Host& host, Device& device)
{
    forEachField<0u, hostOnlyField | Without>([](const auto&, const auto& h, auto& d) { upload(h, d); }, host,
                                              device);
}

// What a step changes (no fixed array) with the flags With, back into the host's group.
template <unsigned With = 0u, unsigned Without = 0u, class Host, class Device>
void downloadFields(const Device& device, Host& host)
{
    forEachField<With, hostOnlyField | fixedField | Without>(
        [](const auto&, auto& h, const auto& d) { download(d, h); }, host, device);
}

// The device memory held by a group's mirror [bytes].
template <class Device>
std::size_t mirrorBytes(const Device& device)
{
    std::size_t total = 0;
    forEachField<0u>([&](const auto&, const auto& d) { total += deviceBytes(d); }, device);
    return total;
}

// What uploadFields<Without> allocates for a host group [bytes] (no device needed).
template <unsigned Without = 0u, class Host>
std::size_t mirrorBytesFor(const Host& host)
{
    std::size_t total = 0;
    forEachField<0u, hostOnlyField | Without>([&](const auto&, const auto& h) { total += sizeBytes(h); },
                                              host);
    return total;
}

}  // namespace
}  // namespace rockfrac
