// Uses every ShaderToy uniform at least once.
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = fragCoord / iResolution.xy;
    float t = iTime + iTimeDelta + float(iFrame) / max(iFrameRate, 1.0);
    vec4 date = iDate;
    float channelTimes = iChannelTime[0] + iChannelTime[1] + iChannelTime[2] + iChannelTime[3];
    vec3 res = iChannelResolution[1] + iChannelResolution[2];
    float sr = iSampleRate / 44100.0;
    vec4 m = iMouse / iResolution.xyxy;
    vec3 tex = texture(iChannel0, uv).rgb + texture(iChannel1, uv).rgb
             + texture(iChannel2, uv).rgb + texture(iChannel3, uv).rgb;
    fragColor = vec4(tex * 0.25 + 0.0 * (t + date.w + channelTimes + res.x + sr + m.x), 1.0);
}
