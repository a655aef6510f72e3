#include "render/encoder.hpp"

#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <mutex>

#include "render/yuv.hpp"
#include "util/output_place.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
}

namespace render {
namespace {

// libavcodec's and x264's own log lines never reach the terminal: the last error-level line
// is kept and becomes part of our one-line message when something fails. Kept per thread: each
// encoder runs on a thread of its own (--both has three), and libav calls the callback on the
// thread whose call logs, so one encoder's message never carries another's line (it was one
// process-wide string).
thread_local std::string last_log;

void keepLog(void* object, int level, const char* format, va_list args) {
  if (level > AV_LOG_ERROR) return;
  char line[512];
  int prefix = 1;
  av_log_format_line(object, level, format, args, line, sizeof line, &prefix);
  std::string text(line);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  last_log = text;
}

std::string lastLog() {
  return last_log;
}

}  // namespace

struct VideoEncoder::State {
  std::string path, temp;
  EncoderSettings settings;
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  Yuv420Converter converter;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  long long count = 0;
  bool header_written = false, finished = false;

  ~State() {
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&codec);
    if (format) {
      if (format->pb) avio_closep(&format->pb);
      avformat_free_context(format);
    }
    if (!finished && !temp.empty()) std::remove(temp.c_str());
  }

  std::string error(const std::string& what, int code = 0) const {
    char text[AV_ERROR_MAX_STRING_SIZE] = "";
    if (code) av_strerror(code, text, sizeof text);
    const std::string log = lastLog();
    return path + ": " + what + (code ? std::string(": ") + text : "") +
           (log.empty() ? "" : " (" + log + ")");
  }

  // Encodes the picture in `frame`, and writes what the encoder has ready.
  rb::Status send() {
    frame->pts = count++;
    if (int r = avcodec_send_frame(codec, frame); r < 0)
      return rb::Status::fault(error("encoding failed", r));
    if (auto e = drain()) return rb::Status::fault(*e);
    return {};
  }

  // Moves every packet the encoder has ready into the file.
  std::optional<std::string> drain() {
    for (;;) {
      const int r = avcodec_receive_packet(codec, packet);
      if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return std::nullopt;
      if (r < 0) return error("encoding failed", r);
      packet->duration = 1;  // one frame, in the codec's 1/fps time base
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      const int w = av_interleaved_write_frame(format, packet);
      if (w < 0) return error("writing failed", w);
    }
  }
};

VideoEncoder::VideoEncoder() : state_(std::make_unique<State>()) {}
VideoEncoder::~VideoEncoder() = default;

const std::string& VideoEncoder::temporaryPath() const {
  return state_->temp;
}

long long VideoEncoder::frames() const {
  return state_->count;
}

rb::Result<std::unique_ptr<VideoEncoder>> VideoEncoder::open(const std::string& path,
                                                             const EncoderSettings& settings) {
  std::unique_ptr<VideoEncoder> encoder(new VideoEncoder());
  State& s = *encoder->state_;
  s.path = path;
  s.settings = settings;
  if (settings.width % 2 || settings.height % 2)
    return rb::Error{"", path + ": width and height must be even"};
  // Hidden and not ending in .mp4 (no *.mp4 glob takes a half-written file); the format is
  // named explicitly below, so the name need not say it. Through links (util/output_place.hpp).
  s.temp = rb::outputPlace(path).temporary;
  if (s.temp.empty())  // a device, pipe or descriptor, which would be written in place
    return rb::Error{"", path + ": is not a regular file (an MP4 must be written to a file)"};

  static std::once_flag logging;  // (encoders may open on several threads at once)
  std::call_once(logging, [] {
    av_log_set_level(AV_LOG_ERROR);
    av_log_set_callback(keepLog);
  });
  if (avformat_alloc_output_context2(&s.format, nullptr, "mp4", s.temp.c_str()) < 0)
    return rb::machineError(s.error("cannot set up an MP4 file"));
  const AVCodec* h264 = avcodec_find_encoder_by_name("libx264");
  if (!h264) return rb::machineError(s.error("libavcodec has no libx264 encoder"));
  s.codec = avcodec_alloc_context3(h264);
  AVCodecContext* c = s.codec;
  c->width = settings.width;
  c->height = settings.height;
  c->time_base = AVRational{1, settings.fps};
  c->framerate = AVRational{settings.fps, 1};
  c->pix_fmt = AV_PIX_FMT_YUV420P;
  c->gop_size = 2 * settings.fps;
  c->thread_count = settings.threads;
  c->color_primaries = AVCOL_PRI_BT709;
  c->color_trc = AVCOL_TRC_BT709;
  c->colorspace = AVCOL_SPC_BT709;
  c->color_range = AVCOL_RANGE_MPEG;
  c->chroma_sample_location = AVCHROMA_LOC_LEFT;  // as render/yuv.cpp samples it
  if (s.format->oformat->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  av_opt_set(c->priv_data, "preset", settings.preset.c_str(), 0);
  av_opt_set(c->priv_data, "crf", std::to_string(settings.crf).c_str(), 0);
  if (int r = avcodec_open2(c, h264, nullptr); r < 0)
    return rb::machineError(s.error("cannot open libx264", r));

  s.stream = avformat_new_stream(s.format, nullptr);
  s.stream->time_base = c->time_base;
  avcodec_parameters_from_context(s.stream->codecpar, c);
  if (int r = avio_open(&s.format->pb, s.temp.c_str(), AVIO_FLAG_WRITE); r < 0) {
    char reason[AV_ERROR_MAX_STRING_SIZE] = "";
    av_strerror(r, reason, sizeof reason);
    return rb::Error{"", rb::cannotWriteIn(path, reason)};
  }
  AVDictionary* options = nullptr;
  av_dict_set(&options, "movflags", "+faststart", 0);
  const int r = avformat_write_header(s.format, &options);
  av_dict_free(&options);
  if (r < 0) return rb::machineError(s.error("cannot write the MP4 header", r));
  s.header_written = true;

  s.frame = av_frame_alloc();
  s.frame->format = AV_PIX_FMT_YUV420P;
  s.frame->width = settings.width;
  s.frame->height = settings.height;
  s.frame->color_primaries = AVCOL_PRI_BT709;
  s.frame->color_trc = AVCOL_TRC_BT709;
  s.frame->colorspace = AVCOL_SPC_BT709;
  s.frame->color_range = AVCOL_RANGE_MPEG;
  s.frame->chroma_location = AVCHROMA_LOC_LEFT;
  if (av_frame_get_buffer(s.frame, 0) < 0) return rb::machineError(s.error("out of memory"));
  s.packet = av_packet_alloc();
  return encoder;
}

rb::Status VideoEncoder::add(const Image& image) {
  State& s = *state_;
  if (image.width != s.settings.width || image.height != s.settings.height)
    return rb::Status::fault(s.error("frame size does not match the video"));
  if (av_frame_make_writable(s.frame) < 0) return rb::Status::fault(s.error("out of memory"));
  AVFrame* f = s.frame;
  s.converter.convert(image, {f->data[0], f->data[1], f->data[2], f->linesize[0], f->linesize[1]});
  return s.send();
}

rb::Status VideoEncoder::add(const Yuv420Image& picture) {
  State& s = *state_;
  const int w = s.settings.width, h = s.settings.height;
  if (picture.width != w || picture.height != h)
    return rb::Status::fault(s.error("frame size does not match the video"));
  if (av_frame_make_writable(s.frame) < 0) return rb::Status::fault(s.error("out of memory"));
  AVFrame* f = s.frame;
  av_image_copy_plane(f->data[0], f->linesize[0], picture.y(), w, w, h);
  av_image_copy_plane(f->data[1], f->linesize[1], picture.u(), w / 2, w / 2, h / 2);
  av_image_copy_plane(f->data[2], f->linesize[2], picture.v(), w / 2, w / 2, h / 2);
  return s.send();
}

rb::Status VideoEncoder::finish(const std::string& final_path) {
  State& s = *state_;
  if (!final_path.empty()) s.path = final_path;
  if (int r = avcodec_send_frame(s.codec, nullptr); r < 0)
    return rb::Status::fault(s.error("encoding failed", r));
  if (auto e = s.drain()) return rb::Status::fault(*e);
  if (int r = av_write_trailer(s.format); r < 0)
    return rb::Status::fault(s.error("writing failed", r));
  if (int r = avio_closep(&s.format->pb); r < 0)
    return rb::Status::fault(s.error("writing failed", r));
  std::error_code ec;
  std::filesystem::rename(s.temp, rb::outputPlace(s.path).target, ec);
  if (ec)
    return rb::Status::fault(s.error("cannot move the finished file into place: " + ec.message()));
  s.finished = true;
  return {};
}

}  // namespace render
