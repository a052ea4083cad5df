// SPDX-License-Identifier: MIT
// Sets ConfigComp's generated vector holders from configuration texts, as ConfigAdmin does,
// and prints what they hold.
public class VectorHolderCheck {
    public static void main(String[] args) throws Exception {
        DoubleVectorHolder weights = new DoubleVectorHolder();
        weights.stringFrom(" 0.5, 1.5 ,2");
        StringVectorHolder order = new StringVectorHolder();
        order.stringFrom("first, second");
        StringVectorHolder none = new StringVectorHolder();
        none.stringFrom("");
        System.out.println(weights.value.size() + ":" + weights + "|" + order.value.get(1) + "|"
                           + none.value.size());
        try {
            weights.stringFrom("0.5,x");
            System.out.println("accepted");
        } catch (NumberFormatException e) {
            System.out.println("refused, kept " + weights);
        }
    }
}
