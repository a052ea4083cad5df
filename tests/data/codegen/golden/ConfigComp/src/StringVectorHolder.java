// -*- Java -*-
// StringVectorHolder.java: holds the vector<string> configuration parameters of ConfigComp.

import java.util.Vector;

import jp.go.aist.rtm.RTC.util.ValueHolder;

/**
 * A vector<string> configuration parameter, bound with bindParameter(). OpenRTM-aist Java
 * holds single values only; the text of a vector parameter is a comma-separated list.
 */
public class StringVectorHolder implements ValueHolder {
    /** The parameter's elements. */
    public Vector<String> value = new Vector<String>();

    public StringVectorHolder() {
    }

    public StringVectorHolder(final Vector<String> initialValue) {
        value = initialValue;
    }

    /**
     * Sets the elements from the comma-separated text of the parameter; an empty text is an
     * empty vector.
     *
     * @param def_val the parameter's text
     * @exception Exception an item is no String
     */
    public void stringFrom(final String def_val) throws Exception {
        Vector<String> parsed = new Vector<String>();
        if (def_val.trim().length() > 0) {
            for (String item : def_val.split(",", -1)) {
                parsed.add(item.trim());
            }
        }
        value = parsed;
    }

    /** The elements as the comma-separated text stringFrom() reads. */
    public String toString() {
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < value.size(); ++i) {
            if (i > 0) {
                text.append(",");
            }
            text.append(value.get(i));
        }
        return text.toString();
    }
}
