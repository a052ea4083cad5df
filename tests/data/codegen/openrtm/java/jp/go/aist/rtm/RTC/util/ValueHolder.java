// SPDX-License-Identifier: MIT
// Stand-in for OpenRTM-aist Java's holder interface, so that generated holders compile without
// OpenRTM-aist installed: ConfigAdmin sets a bound parameter through stringFrom().
package jp.go.aist.rtm.RTC.util;

public interface ValueHolder {
    void stringFrom(final String def_val) throws Exception;
}
